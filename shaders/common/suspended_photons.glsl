// Photons suspended at the driver's loop cap (common/loop_budget.glsl) and
// resumed by the next dispatch, so that tracer.max_steps is honoured where
// the driver ends long loops (llvmpipe): a photon whose budget runs out
// between two steps stores its state here instead of being cut off, and
// PhotonStage dispatches the suspended photons again until none is left.
// A photon that ran out within its first pass of a dispatch makes no
// progress by resuming, and is cut off (counted) instead, so the rounds end.
// Compiled only where the budget is on (EIKON_LOOP_BUDGET > 0). GLSL only.
#if EIKON_LOOP_BUDGET > 0
#define EIKON_RESUMABLE 1

// Members: layout::GpuSuspendedPhoton.
struct SuspendedPhoton { EIKON_GPU_SUSPENDED_PHOTON };
layout(std430, binding = kSuspendedIn) readonly buffer SuspendedIn { SuspendedPhoton suspended_in[]; };
layout(std430, binding = kSuspendedOut) writeonly buffer SuspendedOut { SuspendedPhoton suspended_out[]; };
// Members: layout::GpuSuspendedCount.
layout(std430, binding = kSuspendedCount) buffer SuspendedCount { EIKON_GPU_SUSPENDED_COUNT };

uniform uint resuming;              // 0: this dispatch emits photons; 1: it resumes suspended_in
uniform uint suspended_capacity;    // entries suspended_out holds
#else
#define EIKON_RESUMABLE 0
#endif

const int kSuspended = -1;  // a fate that is not a tally: the photon goes on in the next dispatch

// What a photon whose loop budget ran out becomes: suspended when this
// dispatch moved it on, cut off when it could not (see above).
int out_of_loops(uint passes) {
#if EIKON_RESUMABLE
    return passes > 1u ? kSuspended : kCutOff;
#else
    return kCutOff;
#endif
}
