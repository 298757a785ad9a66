// The 3×3×3 smoothing of the stored photon radiance ([Sun08] §4.4):
// fluence and power-weighted direction are filtered with the binomial kernel
// [1 2 1]/4 along each axis (weights outside the grid left out and the rest
// renormalised), for the view pass to read; `scale` multiplies both (2 for
// the fluence of half the photons, ErrorEstimateStage). With `reach` 0 (the
// wavefront's fluence, which has no noise) the cell is copied unfiltered.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "common/grid_sampling.glsl"

layout(std430, binding = kRawFluence) readonly buffer RawFluence { float raw_fluence[]; };
layout(std430, binding = kRawFluenceDirection) readonly buffer RawFluenceDirection { float raw_fluence_direction[]; };
layout(std430, binding = kFluence) writeonly buffer Fluence { float fluence[]; };
layout(std430, binding = kFluenceDirection) writeonly buffer FluenceDirection { float fluence_direction[]; };

uniform float scale;
uniform int reach;  // 1: the 3×3×3 kernel; 0: the cell itself

void main() {
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(cell, grid.resolution.xyz))) return;
    vec3 phi = vec3(0.0f);
    vec3 direction = vec3(0.0f);
    float weights = 0.0f;
    for (int dz = -reach; dz <= reach; ++dz)
        for (int dy = -reach; dy <= reach; ++dy)
            for (int dx = -reach; dx <= reach; ++dx) {
                ivec3 neighbour = cell + ivec3(dx, dy, dz);
                if (any(lessThan(neighbour, ivec3(0))) || any(greaterThanEqual(neighbour, grid.resolution.xyz))) continue;
                float weight = float((2 - abs(dx)) * (2 - abs(dy)) * (2 - abs(dz)));
                uint index = 3u * uint(grid_linear_index(neighbour));
                phi += weight * vec3(raw_fluence[index], raw_fluence[index + 1u], raw_fluence[index + 2u]);
                direction += weight * vec3(raw_fluence_direction[index], raw_fluence_direction[index + 1u],
                                           raw_fluence_direction[index + 2u]);
                weights += weight;
            }
    uint index = 3u * uint(grid_linear_index(cell));
    phi *= scale / weights;
    direction *= scale / weights;
    fluence[index + 0u] = phi.r;
    fluence[index + 1u] = phi.g;
    fluence[index + 2u] = phi.b;
    fluence_direction[index + 0u] = direction.x;
    fluence_direction[index + 1u] = direction.y;
    fluence_direction[index + 2u] = direction.z;
}
