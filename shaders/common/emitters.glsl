// The lights' emitters as the light passes see them (members:
// layout::GpuEmitter, built by render/stages/PhotonEmission); the spot
// profile is common/spot_profile.glsl, shared with C++. GLSL only.
struct Emitter { EIKON_GPU_EMITTER };
layout(std430, binding = kEmitters) readonly buffer Emitters { Emitter emitters[]; };
uniform uint emitter_count;

#include "common/spot_profile.glsl"
