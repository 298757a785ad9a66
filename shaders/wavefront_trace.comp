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
const uint kUnbranched = 0xFFFFFFu;  // history of a ray that ended before its branch's reflection
uniform vec3 power_unit;      // W per fixed-point tally unit, per channel

#include "common/wavefront_emission.glsl"
#include "common/wavefront_rays.glsl"

// A patch corner: the ray of point u, depositing nothing.
Corner trace_corner(uint emitter_index, uint face, vec2 u) {
    atomicAdd(traced_rays, 1u);
    return trace_ray(emitter_index, face, u, vec3(0.0f));
}

uint corner_history(Corner corner) { return floatBitsToUint(corner.power.w); }
uint corner_fate_code(Corner corner) { return floatBitsToUint(corner.absorbed.w); }
int corner_fate(Corner corner) { return int(corner_fate_code(corner) & 15u); }
int corner_receiver(Corner corner) { return int(corner_fate_code(corner) >> 4) - 1; }

#include "common/wavefront_deposits.glsl"

// The receiver whose plane all the patch's corners reached with one history
// — on its square (received) or past its edge (escaped after crossing the
// plane there) — or −1: the patch's footprint is then a triangle in that
// plane, cut by the square's edges.
int footprint_receiver(Patch p) {
    int r = corner_receiver(p.corners[0]);
    if (r < 0) return -1;
    for (int k = 0; k < 3; ++k) {
        int fate = corner_fate(p.corners[k]);
        if (corner_receiver(p.corners[k]) != r || (fate != kReceived && fate != kEscaped) ||
            corner_history(p.corners[k]) != corner_history(p.corners[0]))
            return -1;
    }
    return r;
}

bool corners_agree(Patch p) {
    return corner_history(p.corners[0]) == corner_history(p.corners[1]) &&
           corner_history(p.corners[1]) == corner_history(p.corners[2]) &&
           corner_fate_code(p.corners[0]) == corner_fate_code(p.corners[1]) &&
           corner_fate_code(p.corners[1]) == corner_fate_code(p.corners[2]);
}

bool reaches_grid(Patch p) { return p.corners[0].exit.w + p.corners[1].exit.w + p.corners[2].exit.w > 0.0f; }

#if EIKON_STORE_FLUENCE > 0
// The fluence of a finished patch's tube, narrower than split_voxels where it
// crosses the grid: its power Φ carried along its axis, the ray of its
// centroid, as the photons' track-length estimator carries a photon's
// (common/fluence_deposits.glsl). A branch's tube starts at its reflection;
// one whose corners all missed the grid, or none of which began the branch,
// deposits nothing.
void deposit_tube(Patch p, vec3 power, vec3 sourced) {
    if (!reaches_grid(p) || !any(greaterThan(sourced, vec3(0.0f)))) return;
    atomicAdd(tube_rays, 1u);
    trace_ray(p.info.x, p.info.z, (p.corners[0].ends.xy + p.corners[1].ends.xy + p.corners[2].ends.xy) / 3.0f, power);
    uint before = atomicAdd(deposit_tallies[0], deposits);
    if (before + deposits < before) atomicAdd(deposit_tallies[1], 1u);
}
#endif

// A patch that is done: its power Φ (patch_power), a third to each corner's
// ledger — its source, absorbed, unfollowed reflections — and what arrives:
// on a receiver's plane, by footprint (the part on the square received, the
// rest escaped); with corners that agree elsewhere, to their common fate;
// else each corner's third to its own fate, at its own texel if received;
// and, where the pass stores fluence, its tube's (deposit_tube).
void finish_patch(Patch p) {
    Emitter emitter = emitters[p.info.x];
    vec3 third = patch_power(emitter, p.info.z, p.corners[0].ends.xy, p.corners[1].ends.xy, p.corners[2].ends.xy) / 3.0f;
    vec3 sourced = vec3(0.0f);
    vec3 absorbed = vec3(0.0f);
    vec3 unfollowed = vec3(0.0f);
    vec3 arriving = vec3(0.0f);
    for (int k = 0; k < 3; ++k) {
        Corner corner = p.corners[k];
        sourced += third * corner.source.rgb;
        absorbed += third * corner.absorbed.rgb;
        unfollowed += third * max(corner.source.rgb - corner.power.rgb - corner.absorbed.rgb, vec3(0.0f));
        arriving += third * corner.power.rgb;
    }
    add_stat(branch < 0 ? kEmitted : kReflected, sourced);
    add_stat(kAbsorbed, absorbed);
    add_stat(kUnfollowed, unfollowed);
    int r = footprint_receiver(p);
    if (r >= 0) {
        float on = deposit_footprint(r, p.corners[0].ends.zw, p.corners[1].ends.zw, p.corners[2].ends.zw, arriving);
        add_stat(kReceived, on * arriving);
        add_stat(kEscaped, (1.0f - on) * arriving);
    } else if (corners_agree(p)) {
        add_stat(corner_fate(p.corners[0]), arriving);
    } else {
        for (int k = 0; k < 3; ++k) {
            Corner corner = p.corners[k];
            int fate = corner_fate(corner);
            add_stat(fate, third * corner.power.rgb);
            if (fate == kReceived)
                deposit_in_texel(corner_receiver(corner), texel_of(corner_receiver(corner), corner.ends.zw),
                                 third * corner.power.rgb);
        }
    }
    atomicAdd(finished_patches, 1u);
#if EIKON_STORE_FLUENCE > 0
    deposit_tube(p, 3.0f * third, sourced);
#endif
}

// The footprint, in texel coordinates of receiver r, that the patch's
// emission rays would have there if they flew straight: the scale of a patch
// whose real footprint is torn, and the measure of the power a texel there
// would get unobstructed. False when a straight ray would miss the plane.
bool straight_footprint(Patch p, int r, out vec2 ends[3]) {
    Emitter emitter = emitters[p.info.x];
    Receiver receiver = receivers[r];
    for (int k = 0; k < 3; ++k) {
        vec3 x;
        vec3 d;
        emission_ray(emitter, p.info.z, p.corners[k].ends.xy, x, d);
        float t = receiver_ray_parameter(x, d, receiver.origin.xyz, receiver.normal.xyz);
        if (t < 0.0f) return false;
        ends[k] = receiver_map_coordinates(x + t * d, receiver.origin.xyz, receiver.axis_u.xyz, receiver.axis_v.xyz,
                                           receiver.origin.w) * float(receiver.map.y);
    }
    return true;
}

float longest_edge(vec2 a, vec2 b, vec2 c) { return max(distance(a, b), max(distance(b, c), distance(c, a))); }

// The spot profile's mean over the patch (1 for other lights): its corners
// carry what reaches them of a unit ray, the patch's power the profile.
float profile_of(Patch p) {
    return patch_profile(emitters[p.info.x], p.info.z, p.corners[0].ends.xy, p.corners[1].ends.xy, p.corners[2].ends.xy);
}

// Whether a patch carries at least min_power of what a texel gets where its
// straight footprint lies (its corners' power over the straight footprint's
// area in texels): splitting a fainter one cannot move much light.
bool carries_power(Patch p, vec2 straight[3]) {
    vec3 arriving = p.corners[0].power.rgb + p.corners[1].power.rgb + p.corners[2].power.rgb;
    float share = max(arriving.r, max(arriving.g, arriving.b)) / 3.0f * profile_of(p);
    return share * 0.5f * abs(twice_signed_area(straight[0], straight[1], straight[2])) >= min_power;
}

// Whether a patch must split for a receiver: while it is larger than
// split_texels there and carries power (carries_power) — the light a grazing ray
// refracts into a wide, faint halo would otherwise split without end, and
// what such a patch misplaces is at most its own power.
// - A footprint in a receiver's plane (footprint_receiver) is measured
//   there, where it overlaps the square; one across the square's edge, where
//   the power is shared by area as if even over the patch, down to
//   tear_texels.
// - Corners that disagree (a shadow edge, a tear of the wavefront at a
//   silhouette or where total internal reflection sets in) are measured by
//   their straight footprint on the receiver a corner reached, down to
//   tear_texels; none reached one, or some fly away from its plane (a tear
//   at its horizon, where light grazes it): the patch stops, as do corners
//   that agree elsewhere.
bool wants_receiver_split(Patch p) {
    vec2 straight[3];
    int r = footprint_receiver(p);
    if (r < 0) {
        if (corners_agree(p)) return false;
        for (int k = 2; k >= 0; --k)
            if (corner_fate(p.corners[k]) == kReceived) r = corner_receiver(p.corners[k]);
        if (r < 0 || !straight_footprint(p, r, straight)) return false;
        return longest_edge(straight[0], straight[1], straight[2]) > tear_texels && carries_power(p, straight);
    }
    float resolution = float(receivers[r].map.y);
    vec2 a = p.corners[0].ends.zw * resolution;
    vec2 b = p.corners[1].ends.zw * resolution;
    vec2 c = p.corners[2].ends.zw * resolution;
    if (any(greaterThan(min(a, min(b, c)), vec2(resolution))) || any(lessThan(max(a, max(b, c)), vec2(0.0f))))
        return false;  // wholly beside the square
    bool straddles = on_square(p.corners[0].ends.zw) != on_square(p.corners[1].ends.zw) ||
                     on_square(p.corners[1].ends.zw) != on_square(p.corners[2].ends.zw);
    if (longest_edge(a, b, c) <= (straddles ? tear_texels : split_texels)) return false;
    return !straight_footprint(p, r, straight) || carries_power(p, straight);
}

float longest_edge(vec3 a, vec3 b, vec3 c) { return max(distance(a, b), max(distance(b, c), distance(c, a))); }

#if EIKON_STORE_FLUENCE > 0
// Whether a patch must split for the fluence in the grid: while its tube is
// wider than split_voxels there and it carries at least min_power of what a
// voxel's cross-section gets unobstructed. The width, in voxels, is that of
// the triangle of its corners where they enter the grid and where they last
// leave it, when they agree (one history, one fate); when they disagree (a
// silhouette, a shadow edge), that of its emission rays flown straight as far
// as the farthest corner got in the grid, so that a torn patch splits only
// down to the tube width, not without end. A patch none of whose corners
// reached the grid does not split for it.
bool wants_grid_split(Patch p) {
    if (!reaches_grid(p)) return false;
    Emitter emitter = emitters[p.info.x];
    vec3 x[3];
    vec3 d[3];
    float farthest = 0.0f;
    bool all_inside = true;
    for (int k = 0; k < 3; ++k) {
        emission_ray(emitter, p.info.z, p.corners[k].ends.xy, x[k], d[k]);
        if (p.corners[k].exit.w > 0.0f) farthest = max(farthest, distance(x[k], p.corners[k].exit.xyz));
        else all_inside = false;
    }
    vec3 voxel = grid.voxel_size.xyz;
    vec3 straight[3];
    for (int k = 0; k < 3; ++k) straight[k] = (x[k] + farthest * d[k]) / voxel;
    float width = longest_edge(straight[0], straight[1], straight[2]);
    if (all_inside && corners_agree(p)) {
        vec3 entry[3];
        for (int k = 0; k < 3; ++k) entry[k] = (x[k] + max(grid_ray_interval(x[k], d[k]).x, 0.0f) * d[k]) / voxel;
        width = max(longest_edge(entry[0], entry[1], entry[2]),
                    longest_edge(p.corners[0].exit.xyz / voxel, p.corners[1].exit.xyz / voxel,
                                 p.corners[2].exit.xyz / voxel));
    }
    if (width <= split_voxels) return false;
    vec3 sourced = p.corners[0].source.rgb + p.corners[1].source.rgb + p.corners[2].source.rgb;
    float share = max(sourced.r, max(sourced.g, sourced.b)) / 3.0f * profile_of(p);
    return share * 0.5f * length(cross(straight[1] - straight[0], straight[2] - straight[0])) >= min_power;
}
#endif

// Whether a branch's patch must split where its corners start the branch
// with different power: across the silhouette of the surface it reflects at,
// where grazing Fresnel reflectance climbs steeply to 1 and then drops to
// nothing beyond the rim, so that the corners' linear interpolation of it
// misses the rim's reflection (−19% of the default scene's reflected power
// at grid_cells 64, −40% of what it reflects onto the floor). It splits
// while that difference times the patch's share of a start patch's power
// (4^−depth) is at least reflection_split — down to max_depth. The main
// wavefront's rim is resolved by its footprint where its light reaches a
// receiver (its unfollowed reflection moves 0.04% from grid_cells 64 to 256
// on the default scene).
bool wants_source_split(Patch p) {
    if (branch < 0) return false;
    float least = 3.0e38f;
    float most = 0.0f;
    for (int k = 0; k < 3; ++k) {
        vec3 s = p.corners[k].source.rgb;
        float strongest = max(s.r, max(s.g, s.b));
        least = min(least, strongest);
        most = max(most, strongest);
    }
    return (most - least) * exp2(-2.0f * float(p.info.y)) >= reflection_split;
}

bool wants_split(Patch p) {
    if (wants_source_split(p)) return true;
#if EIKON_STORE_FLUENCE > 0
    if (wants_grid_split(p)) return true;
#endif
    return wants_receiver_split(p);
}

// A child patch whose corners are the parent's corners or, still to be
// traced (mode 1), edge midpoints of the emission square.
Corner untraced_corner(vec2 u) {
    Corner corner;
    corner.ends = vec4(u, 0.0f, 0.0f);
    corner.power = vec4(0.0f);
    corner.absorbed = vec4(0.0f);
    corner.source = vec4(0.0f);
    corner.exit = vec4(0.0f);
    return corner;
}

void write_child(uint slot, uvec4 info, Corner a, Corner b, Corner c) {
    children[slot].corners[0] = a;
    children[slot].corners[1] = b;
    children[slot].corners[2] = c;
    children[slot].info = info;
}

// The four children of p at slot…slot + 3: its corners and its three edge
// midpoints m01, m12, m20 — as (c0, m01, m20), (m01, c1, m12),
// (m20, m12, c2), (m01, m12, m20) — the midpoints traced by mode 1.
void split_patch(Patch p, uint slot) {
    Corner m01 = untraced_corner(0.5f * (p.corners[0].ends.xy + p.corners[1].ends.xy));
    Corner m12 = untraced_corner(0.5f * (p.corners[1].ends.xy + p.corners[2].ends.xy));
    Corner m20 = untraced_corner(0.5f * (p.corners[2].ends.xy + p.corners[0].ends.xy));
    uvec4 info = uvec4(p.info.x, p.info.y + 1u, p.info.z, 0u);
    write_child(slot + 0u, info, p.corners[0], m01, m20);
    write_child(slot + 1u, info, m01, p.corners[1], m12);
    write_child(slot + 2u, info, m20, m12, p.corners[2]);
    write_child(slot + 3u, info, m01, m12, m20);
    atomicAdd(split_patches, 1u);
}

// Mode 2: patch `index` of the level finishes, or splits into Children.
void refine(uint index) {
    Patch p = patches[index];
    bool splitting = wants_split(p);
    if (splitting && p.info.y < max_depth) {
        uint slot = atomicAdd(child_count, 4u);
        if (slot + 4u <= capacity) {
            split_patch(p, slot);
            return;
        }
    }
    if (splitting) atomicAdd(limited_patches, 1u);
    finish_patch(p);
}

// Mode 0: seed patch `index` of this chunk, half of cell first_cell + index / 2
// of the emission domain's faces of grid_cells² cells, its corners to be traced.
void seed(uint index) {
    uint cell = first_cell + index / 2u;
    uint face = cell / (grid_cells * grid_cells);
    uint in_face = cell % (grid_cells * grid_cells);
    vec2 low = vec2(float(in_face % grid_cells), float(in_face / grid_cells)) / float(grid_cells);
    float size = 1.0f / float(grid_cells);
    vec2 other = (index % 2u == 0u) ? low + vec2(size, 0.0f) : low + vec2(0.0f, size);
    write_child(index, uvec4(seed_emitter, 0u, face, 0u), untraced_corner(low), untraced_corner(other),
                untraced_corner(low + vec2(size)));
}

// Mode 1: ray `job` of the children. After seeding, corner job % 3 of patch
// job / 3; after a split, midpoint job % 3 (m01, m12, m20) of the four
// children at 4·(job / 3), written to each child that has it.
void trace_job(uint job) {
    uint which = job % 3u;
    uint first = job / 3u;
    if (seeded_jobs != 0u) {
        children[first].corners[which] =
            trace_corner(children[first].info.x, children[first].info.z, children[first].corners[which].ends.xy);
        return;
    }
    uint slot = 4u * first;
    if (which == 0u) {  // m01: child 0 corner 1, child 1 corner 0, child 3 corner 0
        Corner m = trace_corner(children[slot].info.x, children[slot].info.z, children[slot].corners[1].ends.xy);
        children[slot].corners[1] = m;
        children[slot + 1u].corners[0] = m;
        children[slot + 3u].corners[0] = m;
    } else if (which == 1u) {  // m12: child 1 corner 2, child 2 corner 1, child 3 corner 1
        Corner m = trace_corner(children[slot].info.x, children[slot].info.z, children[slot + 1u].corners[2].ends.xy);
        children[slot + 1u].corners[2] = m;
        children[slot + 2u].corners[1] = m;
        children[slot + 3u].corners[1] = m;
    } else {  // m20: child 0 corner 2, child 2 corner 0, child 3 corner 2
        Corner m = trace_corner(children[slot].info.x, children[slot].info.z, children[slot].corners[2].ends.xy);
        children[slot].corners[2] = m;
        children[slot + 2u].corners[0] = m;
        children[slot + 3u].corners[2] = m;
    }
}

void main() {
    uint id = gl_GlobalInvocationID.x;
    if (id >= patch_count) return;
    if (mode == 0u) seed(id);
    else if (mode == 1u) trace_job(id);
    else refine(id);
}
