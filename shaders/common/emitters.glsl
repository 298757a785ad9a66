// The lights' emitters as the light passes see them (C++ mirror:
// layout::GpuEmitter, built by render/stages/PhotonEmission); the spot
// profile is common/spot_profile.glsl, shared with C++. GLSL only.
struct Emitter {
    vec4 origin;        // w: kind (0 cone, 1 disk, 2 glowing volume: common/volume_glow.glsl)
    vec4 axis;          // w: cone: versine 1 − cos of its half-angle; disk: radius
    vec4 tangent;
    vec4 bitangent;
    vec4 photon_power;  // rgb W per photon where the spot profile is 1
    vec4 spot;          // xyz: spot axis; w: versine of the outer half-angle (< 0: none)
    vec4 spot_edge;     // x: versine of the inner half-angle
    uvec4 photons;      // x: first photon, y: count, z, w: strata
};
layout(std430, binding = kEmitters) readonly buffer Emitters { Emitter emitters[]; };
uniform uint emitter_count;

#include "common/spot_profile.glsl"
