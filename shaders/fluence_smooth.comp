// The stored radiance for the view pass to read. Photons' fluence and
// power-weighted direction ([Sun08] §4.4) are smoothed with the 3×3×3
// binomial kernel [1 2 1]/4 along each axis (weights outside the grid left
// out and the rest renormalised); `scale` multiplies both (2 for the fluence
// of half the photons, ErrorEstimateStage). With `reach` 0 (the wavefront's
// fluence, which has no noise) the cell is taken as it is, and with
// EIKON_FIXED_FLUENCE (the wavefront's tallies, common/fluence_deposits.glsl)
// converted from 64-bit fixed point — the scattered power too, for the
// lattice (EIKON_LATTICE_SOURCE).
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "common/grid_sampling.glsl"

#ifndef EIKON_FIXED_FLUENCE
#define EIKON_FIXED_FLUENCE 0
#endif
#ifndef EIKON_LATTICE_SOURCE
#define EIKON_LATTICE_SOURCE 0
#endif

#if EIKON_FIXED_FLUENCE
layout(std430, binding = kRawFluence) readonly buffer RawFluence { uint raw_fluence[]; };
layout(std430, binding = kRawFluenceDirection) readonly buffer RawFluenceDirection { uint raw_fluence_direction[]; };
#if EIKON_LATTICE_SOURCE
layout(std430, binding = kRawScattered) readonly buffer RawScattered { uint raw_scattered[]; };
layout(std430, binding = kScatteredPower) writeonly buffer ScatteredPower { float scattered_power[]; };
#endif
uniform vec3 fluence_unit;    // W·m per unit of track, per channel
uniform float direction_unit;  // W·m per unit of the direction sums
uniform vec3 scattered_unit;  // W per unit of scattered power, per channel
#else
layout(std430, binding = kRawFluence) readonly buffer RawFluence { float raw_fluence[]; };
layout(std430, binding = kRawFluenceDirection) readonly buffer RawFluenceDirection { float raw_fluence_direction[]; };
#endif
layout(std430, binding = kFluence) writeonly buffer Fluence { float fluence[]; };
layout(std430, binding = kFluenceDirection) writeonly buffer FluenceDirection { float fluence_direction[]; };

uniform float scale;
uniform int reach;  // 1: the 3×3×3 kernel; 0: the cell itself

#if EIKON_FIXED_FLUENCE
// The 64-bit word pair (low, high) as a number, two's complement if `signed_`.
float wide_value(uint low, uint high, bool signed_) {
    if (signed_ && high >= 0x80000000u) {
        uint magnitude_low = ~low + 1u;
        uint magnitude_high = ~high + (magnitude_low == 0u ? 1u : 0u);
        return -float(double(magnitude_high) * 4294967296.0lf + double(magnitude_low));
    }
    return float(double(high) * 4294967296.0lf + double(low));
}

void main() {
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(cell, grid.resolution.xyz))) return;
    uint index = 3u * uint(grid_linear_index(cell));
    uint words = 2u * index;
    for (int c = 0; c < 3; ++c) {
        uint w = words + uint(2 * c);
        fluence[index + uint(c)] =
            scale * wide_value(raw_fluence[w], raw_fluence[w + 1u], false) * fluence_unit[c] / grid.voxel_size.w;
        fluence_direction[index + uint(c)] = scale * wide_value(raw_fluence_direction[w], raw_fluence_direction[w + 1u], true) *
                                             direction_unit / grid.voxel_size.w;
#if EIKON_LATTICE_SOURCE
        scattered_power[index + uint(c)] = wide_value(raw_scattered[w], raw_scattered[w + 1u], false) * scattered_unit[c];
#endif
    }
}
#else
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
#endif
