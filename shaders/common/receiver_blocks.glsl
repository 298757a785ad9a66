// Receivers as shaders see them (members: layout::GpuReceiver; a uniform
// block, bridge/layout/GpuLayouts.h says why) and their irradiance maps,
// read as a buffer texture of the ReceiverMaps buffer that
// receiver_filter.comp writes (for the same reason: render/stages/ReceiverMaps.h).
// GLSL only; the geometry lives in common/receiver.glsl, and where rays
// cross the receivers, shared with C++, in common/receiver_hits.glsl.
struct Receiver { EIKON_GPU_RECEIVER };

layout(std140, binding = kReceivers) uniform Receivers { Receiver receivers[kMaxReceivers]; };
layout(binding = kReceiverMapTexture) uniform samplerBuffer receiver_map_texels;  // RGB per texel, W/m²

// The scene's receivers: program option EIKON_RECEIVERS
// (ReceiverMaps::countOption). A constant, so that the loops over the
// receivers unroll and read the block at constant offsets: llvmpipe runs a
// loop whose count it learns at run time with mask bookkeeping every turn,
// and reads the block at the loop's index by gathering (the direct pass of
// image_space_caustics.comp on deforming_blob took 6.3 ms that way, 3.0
// unrolled, on two cores). The loops unroll only without `continue` or
// `break`: their bodies choose by selects.
const uint receiver_count = uint(EIKON_RECEIVERS);

// Receiver r's place in the block as a lane-varying index reads it: the
// constant 0 where the scene has one receiver, so that its fields are
// loaded once for all lanes (llvmpipe gathers a block's fields lane by
// lane at an index it cannot tell is the same in every lane).
int receiver_slot(int r) { return receiver_count == 1u ? 0 : r; }

#include "common/receiver_hits.glsl"

// Irradiance of a receiver's map at uv, bilinear between texel centres.
vec3 receiver_irradiance_at(int r, vec2 uv) {
    r = receiver_slot(r);
    uint resolution = receivers[r].map.y;
    vec2 texel = uv * float(resolution) - 0.5f;
    ivec2 base = ivec2(floor(texel));
    vec2 f = texel - vec2(base);
    vec3 sum = vec3(0.0f);
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            ivec2 t = clamp(base + ivec2(i, j), ivec2(0), ivec2(int(resolution) - 1));
            int index = int(receivers[r].map.x + uint(t.y) * resolution + uint(t.x));
            float weight = (i == 0 ? 1.0f - f.x : f.x) * (j == 0 ? 1.0f - f.y : f.y);
            sum += weight * texelFetch(receiver_map_texels, index).rgb;
        }
    }
    return sum;
}
