// Wavefront pass: adaptive wavefront tracing by the intensity law
// ([Ihrke07] §4.2.2–4.2.3, after Enquist and Runborg). A light's emission
// domain (common/wavefront_emission.glsl: one or six square faces) is cut
// into triangular patches whose corners are rays, traced deterministically
// with the photons' march through the graded field and its sharp surfaces,
// each wavefront following one branch of the Fresnel tree
// (common/wavefront_rays.glsl). A patch whose footprint on a receiver is
// larger than `split_texels`, or whose corners disagree in history (fate,
// receiver, surfaces crossed, total internal reflections) while larger than
// `tear_texels`, splits in four, unless it is too faint to matter
// (`min_power`). A finished patch deposits its power — E = Φ_patch / area,
// eq. 15 — over the texels its footprint covers by exact coverage
// (common/wavefront_deposits.glsl), so power is conserved even where a
// caustic folds the footprint to a line. Where the pass stores fluence, a
// patch also splits while its tube through the grid is wider than
// `split_voxels`, and a finished patch traces its tube's axis — the ray of
// its centroid — depositing its power along the way by cloud-in-cell
// weights (common/fluence_deposits.glsl), the photons' track-length
// estimator without their noise. No sampling: the same scene gives the same
// receiver bits (fluence sums floats, equal to their rounding).
//
// One program, three modes (uniform `mode`), one invocation a patch or a ray:
//   0 seed:   patch p of this chunk of the emitter's faces of grid_cells²
//             cells (two triangles a cell) into Children[p], corners untraced;
//   1 trace:  the untraced corners of Children, one ray an invocation;
//   2 refine: each patch of Patches finishes (deposits and tallies) or, if it
//             must split and may, writes its four children to Children,
//             their new corners (its edge midpoints) untraced.
//
// Program options (#defines set by WavefrontStage): those of
// common/ray_march.glsl and common/fluence_deposits.glsl, and
//   EIKON_LOOP_BUDGET      loop iterations an invocation may run where the driver caps them
//                          (common/loop_budget.glsl); 0: no cap
layout(local_size_x = 64) in;

#include "common/grid_sampling.glsl"
#include "common/loop_budget.glsl"
#include "common/ray_step.glsl"
#include "common/attenuation.glsl"
#include "common/sampling.glsl"
#include "common/receiver.glsl"
#include "common/receiver_blocks.glsl"
#include "common/straight_flight.glsl"
#include "common/step_size.glsl"
#include "common/fresnel.glsl"
#include "common/sharp_surfaces.glsl"
#include "common/ray_march.glsl"
#include "common/emitters.glsl"
#include "common/footprint_coverage.glsl"
#include "common/photon_stats_block.glsl"
#include "common/pass_loops.glsl"
#include "common/fluence_deposits.glsl"

// C++: layout::GpuWavefrontCorner and GpuWavefrontPatch.
struct Corner { EIKON_GPU_WAVEFRONT_CORNER };
struct Patch { EIKON_GPU_WAVEFRONT_PATCH };
layout(std430, binding = kWavefrontPatches) readonly buffer Patches { Patch patches[]; };
layout(std430, binding = kWavefrontChildren) buffer Children { Patch children[]; };
// Members: layout::GpuWavefrontCounters.
layout(std430, binding = kWavefrontCounters) buffer Counters { EIKON_GPU_WAVEFRONT_COUNTERS };
layout(std430, binding = kReceiverTallies) buffer ReceiverTallies { uint receiver_tallies[]; };  // [2·(3·texel + channel) + word]

uniform uint mode;            // 0 seed, 1 trace, 2 refine
uniform uint patch_count;     // patches (seed, refine) or rays (trace) of this dispatch
uniform uint seeded_jobs;     // trace: 1 after a seed, 0 after a refinement
uniform uint first_cell;      // seed: the chunk's first cell of the emission grid
uniform uint seed_emitter;    // seed: the emitter
uniform uint grid_cells;      // cells per edge of the emission square at depth 0
uniform uint max_depth;       // splits a patch may descend by
uniform uint capacity;        // patches the children buffer holds (a multiple of 4)
uniform float split_texels;   // largest footprint edge, in texels, of a finished patch
uniform float tear_texels;    // largest straight footprint edge, in texels, of a finished torn patch
uniform float min_power;      // share of a texel's (voxel's) unobstructed power below which a patch does not split
uniform float reflection_split;  // share of a start patch's power a branch's patch may misplace by its corners' sources
uniform float split_voxels;   // largest width, in voxels, of a finished patch's tube through the grid (fluence)
uniform int channel;          // −1: all channels at once; 0, 1, 2: this channel only (dispersion)
uniform int branch;           // −1: the main wavefront; b: the branch reflected at Fresnel event b
uniform vec3 power_unit;      // W per fixed-point tally unit, per channel
uniform uint emission_faces;  // faces of this emitter's emission domain (WavefrontStage::emissionFaces)

// The counters of the shared text: atomics on the Counters and PhotonStats blocks.
void count_traced_ray() { atomicAdd(traced_rays, 1u); }
void count_finished_patch() { atomicAdd(finished_patches, 1u); }
void count_split_patch() { atomicAdd(split_patches, 1u); }
void count_limited_patch() { atomicAdd(limited_patches, 1u); }
void count_march(uint steps, float max_invariant_error, uvec2 error_units) {
    uint before = atomicAdd(step_tallies[0], steps);
    if (before + steps < before) atomicAdd(step_tallies[1], 1u);
    atomicMax(step_tallies[2], floatBitsToUint(max_invariant_error));
    uint low_before = atomicAdd(invariant_tallies[0], error_units.x);
    atomicAdd(invariant_tallies[1], error_units.y + (low_before + error_units.x < low_before ? 1u : 0u));
}

#include "common/wide_units.glsl"
#include "common/wavefront_emission.glsl"
#include "common/wavefront_rays.glsl"

#include "common/wavefront_deposits.glsl"
#include "common/wavefront_patches.glsl"

// Mode 2: patch `index` of the level finishes, or claims four slots of
// Children and splits into them.
void refine(uint index) {
    Patch p = patches[index];
    bool splitting = wants_split(p);
    settle_patch(p, splitting, claims_children(p, splitting) ? atomicAdd(child_count, 4u) : capacity);
}

void main() {
    uint id = gl_GlobalInvocationID.x;
    if (id >= patch_count) return;
    if (mode == 0u) seed(id);
    else if (mode == 1u) trace_job(id);
    else refine(id);
}
