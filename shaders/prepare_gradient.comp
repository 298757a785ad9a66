// Index preparation: ∇n by central differences of δn between cell centres
// (one-sided at the grid faces), stored with δn as (∇n, δn) so the tracers
// fetch both with one trilinear lookup.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "common/grid_sampling.glsl"

layout(binding = kIndexTexture) uniform sampler3D index_texture;  // r: δn
layout(rgba32f, binding = kGradientImage) writeonly uniform image3D gradient_image;

float delta_at(ivec3 cell) {
    return texelFetch(index_texture, clamp(cell, ivec3(0), grid.resolution.xyz - 1), 0).r;
}

float derivative(ivec3 cell, ivec3 axis, float h) {
    ivec3 lo = max(cell - axis, ivec3(0));
    ivec3 hi = min(cell + axis, grid.resolution.xyz - 1);
    float span = float(dot(hi - lo, axis));
    return span > 0.0f ? (delta_at(hi) - delta_at(lo)) / (span * h) : 0.0f;
}

void main() {
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(cell, grid.resolution.xyz))) return;
    vec3 gradient = vec3(derivative(cell, ivec3(1, 0, 0), grid.voxel_size.x),
                         derivative(cell, ivec3(0, 1, 0), grid.voxel_size.y),
                         derivative(cell, ivec3(0, 0, 1), grid.voxel_size.z));
    imageStore(gradient_image, cell, vec4(gradient, delta_at(cell)));
}
