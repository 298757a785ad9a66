// Index preparation: (∇n, δn) at every cell (common/index_gradient.glsl).
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "common/grid_sampling.glsl"

layout(binding = kIndexTexture) uniform sampler3D index_texture;  // r: δn
layout(rgba32f, binding = kGradientImage) writeonly uniform image3D gradient_image;

float gradient_source(ivec3 cell) { return texelFetch(index_texture, cell, 0).r; }

#include "common/index_gradient.glsl"

void main() {
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(cell, grid.resolution.xyz))) return;
    imageStore(gradient_image, cell, gradient_and_index(cell, grid.resolution.xyz, grid.voxel_size.xyz));
}
