// Photon pass ([Sun08] §4.3–4.4 and §5.3): each invocation emits
// one photon toward the traced region, flies it straight outside the field
// grid (common/straight_flight.glsl) and marches it inside with the chosen
// integrator (common/integrators.glsl) and step policy (uniform, or octree-
// adaptive: common/step_size.glsl), attenuating its power by Beer–Lambert,
// depositing fluence along every voxel its segments cross (track-length
// estimator, 3D DDA) and landing on receivers. The tracer itself is
// common/photon_tracer.glsl, shared with the native pass
// (render/stages/NativePhotonTrace.cpp); this program declares what it
// reads and keeps its tallies as the work group's atomics.
//
// Program options (#defines set by PhotonStage):
//   EIKON_INTEGRATOR       0 Euler, 1 leapfrog, 2 RK4
//   EIKON_OCTREE_STEPS     1: adaptive steps from the step structure
//   EIKON_RENORMALIZE      1: |v| = n(x) after every step
//   EIKON_DISPERSION       1: each photon carries one RGB channel with its own index scale
//   EIKON_STORE_FLUENCE    0 none, 1 where σs > 0, 2 everywhere (common/fluence_deposits.glsl)
//   EIKON_LATTICE_SOURCE   1: also the power scattered per cell (the multiple-scattering lattice's source)
//   EIKON_BOUNCE           1: some receiver reflects photons (receivers[].map.z)
//   EIKON_BARE_MARCH       1: march only (benchmark limit): no attenuation, deposits or receivers
//   EIKON_SHARP_SURFACES   0 none, 1 spheres and boxes, 2 meshes or water too (common/sharp_surface_blocks.glsl)
//   EIKON_VOLUME_GLOW      1: a glowing volume may be an emitter (common/volume_glow.glsl)
//   EIKON_RECORD_PATHS     vertices recorded (position, RGB power) for each of EIKON_RECORDED_PHOTONS
//                          photons: every EIKON_RECORD_STRIDE-th one from photon 0
//   EIKON_RECORD_ENDS      1: where EIKON_RECORDED_PHOTONS photons, every end_stride-th from photon 0,
//                          ended (position, fate, receiver, power), for the discretisation estimate
//                          (ErrorEstimateStage)
//   EIKON_LOOP_BUDGET      loop iterations a photon may run where the driver caps them
//                          (common/loop_budget.glsl); 0: no cap. Where set, a photon that runs
//                          out is suspended and resumed by the next dispatch
//                          (common/suspended_photons.glsl)
layout(local_size_x = 64) in;

#include "common/grid_sampling.glsl"
#include "common/loop_budget.glsl"
#include "common/random.glsl"
#include "common/ray_step.glsl"
#include "common/attenuation.glsl"
#include "common/sampling.glsl"
#include "common/receiver.glsl"
#include "common/receiver_blocks.glsl"
#include "common/straight_flight.glsl"
#include "common/step_size.glsl"
#include "common/fresnel.glsl"
#include "common/sharp_surfaces.glsl"

#ifndef EIKON_RENORMALIZE
#define EIKON_RENORMALIZE 0
#endif
#ifndef EIKON_DISPERSION
#define EIKON_DISPERSION 0
#endif
#ifndef EIKON_BOUNCE
#define EIKON_BOUNCE 0
#endif
#ifndef EIKON_BARE_MARCH
#define EIKON_BARE_MARCH 0
#endif
#ifndef EIKON_RECORD_PATHS
#define EIKON_RECORD_PATHS 0
#endif
#ifndef EIKON_RECORDED_PHOTONS
#define EIKON_RECORDED_PHOTONS 64
#endif
#ifndef EIKON_RECORD_STRIDE
#define EIKON_RECORD_STRIDE 1
#endif
#ifndef EIKON_RECORD_ENDS
#define EIKON_RECORD_ENDS 0
#endif

#include "common/ray_march.glsl"
#include "common/emitters.glsl"
#include "common/suspended_photons.glsl"
#include "common/fluence_deposits.glsl"

layout(std430, binding = kReceiverTallies) buffer ReceiverTallies { uint receiver_tallies[]; };  // [2·(3·texel + channel) + word]

#include "common/photon_stats_block.glsl"

#if EIKON_RECORD_PATHS > 0
layout(std430, binding = kPhotonPaths) writeonly buffer PhotonPaths { vec4 path_vertices[]; };  // xyz, w: 1 written
layout(std430, binding = kPhotonPathPower) writeonly buffer PhotonPathPower { vec4 path_power[]; };  // rgb: W at the vertex
#endif
#if EIKON_RECORD_ENDS
// Per recorded photon two vec4: (end position, fate) and (RGB power at the
// end, receiver it ended on or -1).
layout(std430, binding = kPhotonEnds) writeonly buffer PhotonEnds { vec4 photon_ends[]; };
#endif

uniform uint photon_offset;    // index of this batch's first photon
uniform uint photon_stride;    // invocation id traces photon photon_offset + id · photon_stride
uniform uint checkerboard;     // 1: with photon_stride 2, each half takes a checkerboard of strata (checkerboard_photon)
uniform uint batch_size;
uniform uint seed;
uniform float power_cutoff;    // Russian roulette once every channel is below this fraction of the emitted power
uniform vec3 power_unit;       // W per fixed-point tally unit, per channel

#ifndef EIKON_VOLUME_GLOW
#define EIKON_VOLUME_GLOW 0
#endif
#if EIKON_VOLUME_GLOW
#include "common/volume_glow.glsl"
#endif

// Tallies of this work group, flushed to PhotonStats once by its first
// invocation: a global atomic per work group instead of per photon (64
// photons of at most 2^24 units each cannot overflow a 32-bit word here).
shared uint group_power[3 * kTallyCount];  // [3·tally + channel]
shared uint group_photons[4];
shared uint group_steps;
shared uint group_max_invariant_bits;
shared uint group_deposits;
shared uint group_invariant[2];  // fixed point, low and high word (invariant_units)
shared uint group_surface_events[2];  // reflected, transmitted

// Adds to a 64-bit counter held as two words, carrying into the high word.
void add_wide_power(uint low_word, uint value) {
    uint before = atomicAdd(power_tallies[low_word], value);
    if (before + value < before) atomicAdd(power_tallies[low_word + 1u], 1u);
}

void add_wide_receiver(uint low_word, uint value) {
    uint before = atomicAdd(receiver_tallies[low_word], value);
    if (before + value < before) atomicAdd(receiver_tallies[low_word + 1u], 1u);
}

// The tallies of common/photon_tracer.glsl: atomics on the work group's.
void add_group_power(int index, uint units) { atomicAdd(group_power[index], units); }

void count_surface_event(int kind) { atomicAdd(group_surface_events[kind], 1u); }

void count_photon(int fate) { atomicAdd(group_photons[fate - kEscaped], 1u); }

void count_march(uint steps, float max_invariant_error, uint deposited, uvec2 error_units) {
    atomicAdd(group_steps, steps);
    atomicMax(group_max_invariant_bits, floatBitsToUint(max_invariant_error));
    atomicAdd(group_deposits, deposited);
    uint invariant_before = atomicAdd(group_invariant[0], error_units.x);
    atomicAdd(group_invariant[1], error_units.y + (invariant_before + error_units.x < invariant_before ? 1u : 0u));
}

void record_vertex(uint photon, uint vertex, vec3 x, vec3 power) {
#if EIKON_RECORD_PATHS > 0
    uint slot = photon / uint(EIKON_RECORD_STRIDE);
    if (photon % uint(EIKON_RECORD_STRIDE) == 0u && slot < uint(EIKON_RECORDED_PHOTONS) &&
        vertex < uint(EIKON_RECORD_PATHS)) {
        uint index = slot * uint(EIKON_RECORD_PATHS) + vertex;
        path_vertices[index] = vec4(x, 1.0f);
        path_power[index] = vec4(power, 0.0f);
    }
#endif
}

#if EIKON_RECORD_ENDS
uniform uint end_stride;  // the ends of photons 0, k, 2k, … are kept (a uniform: one program for every k)
#endif

void record_end(uint photon, vec3 x, int fate, int receiver, vec3 power) {
#if EIKON_RECORD_ENDS
    uint slot = photon / end_stride;
    if (photon % end_stride == 0u && slot < uint(EIKON_RECORDED_PHOTONS)) {
        photon_ends[2u * slot] = vec4(x, float(fate));
        photon_ends[2u * slot + 1u] = vec4(power, float(receiver));
    }
#endif
}

#if EIKON_SHARP_SURFACES
uint surface_events = 0u;  // this photon's crossings so far: its random dimensions there
#endif

#include "common/pass_loops.glsl"
#include "common/photon_tracer.glsl"

void flush_group_tallies() {
    for (int i = 0; i < 3 * kTallyCount; ++i)
        if (group_power[i] != 0u) add_wide_power(uint(2 * i), group_power[i]);
    for (int i = 0; i < 4; ++i) atomicAdd(photon_tallies[i], group_photons[i]);
    uint steps_before = atomicAdd(step_tallies[0], group_steps);
    if (steps_before + group_steps < steps_before) atomicAdd(step_tallies[1], 1u);
    atomicMax(step_tallies[2], group_max_invariant_bits);
    uint deposits_before = atomicAdd(deposit_tallies[0], group_deposits);
    if (deposits_before + group_deposits < deposits_before) atomicAdd(deposit_tallies[1], 1u);
    uint invariant_before = atomicAdd(invariant_tallies[0], group_invariant[0]);
    atomicAdd(invariant_tallies[1], group_invariant[1] + (invariant_before + group_invariant[0] < invariant_before ? 1u : 0u));
    atomicAdd(surface_tallies[0], group_surface_events[0]);
    atomicAdd(surface_tallies[1], group_surface_events[1]);
}

void main() {
    if (gl_LocalInvocationIndex == 0u) {
        for (int i = 0; i < 3 * kTallyCount; ++i) group_power[i] = 0u;
        for (int i = 0; i < 4; ++i) group_photons[i] = 0u;
        group_steps = 0u;
        group_max_invariant_bits = 0u;
        group_deposits = 0u;
        group_invariant[0] = 0u;
        group_invariant[1] = 0u;
        group_surface_events[0] = 0u;
        group_surface_events[1] = 0u;
    }
    barrier();
    uint id = gl_GlobalInvocationID.x;
    if (id < batch_size) trace_photon(id);
    barrier();
    if (gl_LocalInvocationIndex == 0u) flush_group_tallies();
}
