// Receivers as shaders see them (members: layout::GpuReceiver; a uniform
// block, bridge/layout/GpuLayouts.h says why) and their irradiance maps,
// read as a buffer texture of the ReceiverMaps buffer that
// receiver_filter.comp writes (for the same reason: render/stages/ReceiverMaps.h).
// GLSL only; the geometry lives in common/receiver.glsl.
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

// Where a segment from a to b first crosses a receiver square.
struct ReceiverHit {
    int receiver;   // -1: none
    float fraction; // position of the hit along the segment, in [0, 1]
    bool lit_side;  // arrived from the side the normal points to
    vec2 map_uv;
};

ReceiverHit first_receiver_crossing(vec3 a, vec3 b) {
    ReceiverHit best = ReceiverHit(-1, 2.0f, false, vec2(0.0f));
    for (uint r = 0u; r < receiver_count; ++r) {
        float da = receiver_signed_distance(a, receivers[r].origin.xyz, receivers[r].normal.xyz);
        float db = receiver_signed_distance(b, receivers[r].origin.xyz, receivers[r].normal.xyz);
        bool crosses = (da > 0.0f) != (db > 0.0f) && da != db;
        float fraction = crosses ? da / (da - db) : 2.0f;
        vec2 uv = receiver_map_coordinates(mix(a, b, fraction), receivers[r].origin.xyz, receivers[r].axis_u.xyz,
                                           receivers[r].axis_v.xyz, receivers[r].origin.w);
        bool on_square = all(greaterThanEqual(uv, vec2(0.0f))) && all(lessThan(uv, vec2(1.0f)));
        if (crosses && fraction < best.fraction && on_square) best = ReceiverHit(int(r), fraction, da > 0.0f, uv);
    }
    return best;
}

// Where the ray x + t·d, 0 ≤ t ≤ reach, first crosses a receiver square,
// and at which t (t_hit): the crossing solved analytically, so that a
// ray may reach as far as it goes (reach may be EIKON_INFINITY). It crosses
// as the segment from x to x + reach·d would (first_receiver_crossing), from
// the plane's lit side to its back or back to front; `fraction` is 0.
ReceiverHit first_receiver_on_ray(vec3 x, vec3 d, float reach, out float t_hit) {
    ReceiverHit best = ReceiverHit(-1, 0.0f, false, vec2(0.0f));
    t_hit = reach;
    for (uint r = 0u; r < receiver_count; ++r) {
        float height = receiver_signed_distance(x, receivers[r].origin.xyz, receivers[r].normal.xyz);
        float approach = dot(d, receivers[r].normal.xyz);
        bool crosses = height > 0.0f ? approach < 0.0f : approach > 0.0f;
        float t = crosses ? -height / approach : 0.0f;
        vec2 uv = receiver_map_coordinates(x + t * d, receivers[r].origin.xyz,
                                           receivers[r].axis_u.xyz, receivers[r].axis_v.xyz, receivers[r].origin.w);
        bool on_square = all(greaterThanEqual(uv, vec2(0.0f))) && all(lessThan(uv, vec2(1.0f)));
        bool first = crosses && t <= reach && t < t_hit && on_square;
        best = first ? ReceiverHit(int(r), 0.0f, height > 0.0f, uv) : best;
        t_hit = first ? t : t_hit;
    }
    return best;
}

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
