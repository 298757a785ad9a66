// Post: linear HDR radiance → exposure 2^EV → filmic curve ([Narkowicz16]'s fit
// of the ACES reference rendering transform) → sRGB encoding → RGBA8.
layout(local_size_x = 8, local_size_y = 8) in;  // over the image, so a wide one stays within the work-group count

#include "common/srgb.glsl"

// The HdrImage buffer read as a buffer texture: a CPU rasterizer fetches
// texels for all lanes at once, where it loads a storage buffer a lane and a
// float at a time (0.5 ms of 1.9 at 640×480 on two cores).
layout(binding = kHdrImageTexture) uniform samplerBuffer hdr_radiance;
layout(std430, binding = kLdrImage) writeonly buffer LdrImage { uint ldr_rgba8[]; };

uniform uvec2 image_size;  // pixels
uniform float exposure_scale;

vec3 aces_filmic(vec3 x) {
    return clamp((x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f), 0.0f, 1.0f);
}


void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, image_size))) return;
    uint i = pixel.y * image_size.x + pixel.x;
    vec3 encoded = srgb_encode(aces_filmic(max(texelFetch(hdr_radiance, int(i)).rgb, vec3(0.0f)) * exposure_scale));
    ldr_rgba8[i] = packUnorm4x8(vec4(encoded, 1.0f));
}
