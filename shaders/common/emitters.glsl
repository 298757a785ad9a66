// The lights' emitters as the light passes see them (members:
// layout::GpuEmitter, built by render/stages/PhotonEmission) and the spot
// profile. GLSL only.
struct Emitter { EIKON_GPU_EMITTER };
layout(std430, binding = kEmitters) readonly buffer Emitters { Emitter emitters[]; };
uniform uint emitter_count;

// A spot light's intensity relative to its axis at a direction of versine
// h = 1 − cos θ from it: 1 inside the inner cone, smoothstep in cos θ (so in
// h) to 0 at the outer cone; versine_outer < 0: no spot (1 everywhere).
// Versines, not cosines: float holds 1 − cos of a hundredth of a degree
// (1.5e-8) to seven digits, and its cosine not at all.
float spot_profile_at_versine(float h, float versine_outer, float versine_inner) {
    if (versine_outer < 0.0f) return 1.0f;
    if (versine_inner >= versine_outer) return h <= versine_outer ? 1.0f : 0.0f;  // hard edge
    float t = clamp((versine_outer - h) / (versine_outer - versine_inner), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// The same for a unit direction and the spot's unit axis: h = |d − axis|²/2,
// which keeps its digits where 1 − dot(d, axis) would cancel.
float spot_profile_about(vec3 axis, float versine_outer, float versine_inner, vec3 direction) {
    vec3 apart = direction - axis;
    return spot_profile_at_versine(0.5f * dot(apart, apart), versine_outer, versine_inner);
}

float spot_profile(Emitter emitter, vec3 direction) {
    return spot_profile_about(emitter.spot.xyz, emitter.spot.w, emitter.spot_edge.x, direction);
}
