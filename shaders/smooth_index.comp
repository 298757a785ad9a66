// One axis of the separable Gaussian that smooths δn before its gradient is
// taken ([Sun08] §4.1: σ = window/6, 9³ by default), so ∇n is
// finite and rays bend smoothly across interfaces. Weights come from the C++
// side, normalised to sum to one; samples past the grid take the edge value.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(binding = kIndexTexture) uniform sampler3D source_texture;  // r: δn
layout(r32f, binding = kSmoothedIndexImage) writeonly uniform image3D target_image;

const int MAX_RADIUS = 31;
uniform int radius;
uniform ivec3 axis;
uniform float weights[MAX_RADIUS + 1];  // weights[|offset|]

void main() {
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    ivec3 size = textureSize(source_texture, 0);
    if (any(greaterThanEqual(cell, size))) return;
    float sum = weights[0] * texelFetch(source_texture, cell, 0).r;
    for (int offset = 1; offset <= radius; ++offset) {
        ivec3 before = clamp(cell - offset * axis, ivec3(0), size - 1);
        ivec3 after = clamp(cell + offset * axis, ivec3(0), size - 1);
        sum += weights[offset] * (texelFetch(source_texture, before, 0).r + texelFetch(source_texture, after, 0).r);
    }
    imageStore(target_image, cell, vec4(sum));
}
