// The lights' emitters as the light passes see them (C++ mirror:
// layout::GpuEmitter, built by render/stages/PhotonEmission) and the spot
// profile. GLSL only.
struct Emitter {
    vec4 origin;        // w: kind (0 cone, 1 disk, 2 glowing volume: common/volume_glow.glsl)
    vec4 axis;          // w: cone: cos of half-angle; disk: radius
    vec4 tangent;
    vec4 bitangent;
    vec4 photon_power;  // rgb W per photon where the spot profile is 1
    vec4 spot;          // xyz: spot axis; w: cos outer half-angle (−2: none)
    vec4 spot_edge;     // x: cos inner half-angle
    uvec4 photons;      // x: first photon, y: count, z, w: strata
};
layout(std430, binding = kEmitters) readonly buffer Emitters { Emitter emitters[]; };
uniform uint emitter_count;

// A spot light's intensity relative to its axis: 1 inside the inner cone,
// smoothstep in cos θ to 0 at the outer cone.
// axis: the spot's unit axis; cos_outer < −1.5: no spot (1 everywhere).
float spot_profile_about(vec3 axis, float cos_outer, float cos_inner, vec3 direction) {
    if (cos_outer < -1.5f) return 1.0f;
    float cos_theta = dot(direction, axis);
    if (cos_inner <= cos_outer) return cos_theta >= cos_outer ? 1.0f : 0.0f;  // hard edge
    return smoothstep(cos_outer, cos_inner, cos_theta);
}

float spot_profile(Emitter emitter, vec3 direction) {
    return spot_profile_about(emitter.spot.xyz, emitter.spot.w, emitter.spot_edge.x, direction);
}
