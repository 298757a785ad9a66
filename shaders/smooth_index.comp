// One axis of the separable Gaussian that smooths δn (common/index_smoothing.glsl)
// over the grid. Weights come from the C++ side (render/stages/GaussianKernel.h),
// normalised to sum to one.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(binding = kIndexTexture) uniform sampler3D source_texture;  // r: δn
layout(r32f, binding = kSmoothedIndexImage) writeonly uniform image3D target_image;

const int MAX_RADIUS = 31;
uniform int radius;
uniform ivec3 axis;
uniform float weights[MAX_RADIUS + 1];  // weights[|offset|]

float smoothing_source(ivec3 cell) { return texelFetch(source_texture, cell, 0).r; }
float smoothing_weight(int offset) { return weights[offset]; }

#include "common/index_smoothing.glsl"

void main() {
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    ivec3 size = textureSize(source_texture, 0);
    if (any(greaterThanEqual(cell, size))) return;
    imageStore(target_image, cell, vec4(smoothed_along_axis(cell, size, axis, radius)));
}
