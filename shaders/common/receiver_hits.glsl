// Receivers as the tracers meet them: the scene's receivers (`receivers`,
// `receiver_count` of them, of struct Receiver, declared by the includer:
// GLSL in common/receiver_blocks.glsl, C++ in render/stages/NativePhotonTrace.cpp)
// and where a segment or a straight ray first crosses one. Shared by GLSL
// and C++; needs common/receiver.glsl.

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
        float da = receiver_signed_distance(a, xyz_of(receivers[r].origin), xyz_of(receivers[r].normal));
        float db = receiver_signed_distance(b, xyz_of(receivers[r].origin), xyz_of(receivers[r].normal));
        bool crosses = (da > 0.0f) != (db > 0.0f) && da != db;
        float fraction = crosses ? da / (da - db) : 2.0f;
        vec2 uv = receiver_map_coordinates(mix(a, b, fraction), xyz_of(receivers[r].origin), xyz_of(receivers[r].axis_u),
                                           xyz_of(receivers[r].axis_v), receivers[r].origin.w);
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
ReceiverHit first_receiver_on_ray(vec3 x, vec3 d, float reach, OUT(float) t_hit) {
    ReceiverHit best = ReceiverHit(-1, 0.0f, false, vec2(0.0f));
    t_hit = reach;
    for (uint r = 0u; r < receiver_count; ++r) {
        float height = receiver_signed_distance(x, xyz_of(receivers[r].origin), xyz_of(receivers[r].normal));
        float approach = dot(d, xyz_of(receivers[r].normal));
        bool crosses = height > 0.0f ? approach < 0.0f : approach > 0.0f;
        float t = crosses ? -height / approach : 0.0f;
        vec2 uv = receiver_map_coordinates(x + t * d, xyz_of(receivers[r].origin),
                                           xyz_of(receivers[r].axis_u), xyz_of(receivers[r].axis_v), receivers[r].origin.w);
        bool on_square = all(greaterThanEqual(uv, vec2(0.0f))) && all(lessThan(uv, vec2(1.0f)));
        bool first = crosses && t <= reach && t < t_hit && on_square;
        best = first ? ReceiverHit(int(r), 0.0f, height > 0.0f, uv) : best;
        t_hit = first ? t : t_hit;
    }
    return best;
}
