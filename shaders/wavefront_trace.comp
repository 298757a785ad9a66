// Wavefront pass: adaptive wavefront tracing ([Ihrke07] §4.2 and §5.2,
// after Enquist and Runborg). A light's emission square (common/emitters.glsl:
// the directions of a point or spot light toward the traced region, the
// positions of a directional light's disk) is cut into triangular patches
// whose corners are rays, traced with the photons' march
// (common/ray_march.glsl) through the graded field and its sharp surfaces,
// deterministically: at a sharp surface a ray follows the transmitted light
// with its Fresnel transmittance (and total internal reflection); the
// reflected part is tallied as unfollowed. A patch whose corners disagree in
// history (fate, receiver, surfaces crossed, total internal reflections)
// splits in four until it is smaller than `tear_texels` on the receiver, one
// whose footprint spans more than `split_texels` texels too; a finished patch deposits its power by the intensity law,
// E = Φ_patch / area, spread over the texels its footprint covers by exact
// coverage (common/footprint_coverage.glsl), so power is conserved even
// where a caustic folds the footprint to a line. No sampling: the same scene
// gives the same bits.
//
// One program, three modes (uniform `mode`), one invocation a patch or a ray:
//   0 seed:   patch p of this chunk of the emitter's grid_cells² cells (two
//             triangles a cell) into Children[p], its corners untraced;
//   1 trace:  the untraced corners of Children, one ray an invocation;
//   2 refine: each patch of Patches finishes (deposits and tallies) or, if it
//             must split and may, writes its four children to Children,
//             their new corners (its edge midpoints) untraced.
//
// Program options (#defines set by WavefrontStage): those of
// common/ray_march.glsl, and
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

struct Corner {
    vec4 ends;      // xy: emission square; zw: receiver map coordinates
    vec4 power;     // rgb: arriving power per unit power density; w: history bits
    vec4 absorbed;  // rgb: absorbed; w: fate | (receiver + 1) << 4
};
struct Patch {
    Corner corners[3];
    uvec4 info;  // x: emitter, y: depth
};
layout(std430, binding = kWavefrontPatches) readonly buffer Patches { Patch patches[]; };
layout(std430, binding = kWavefrontChildren) buffer Children { Patch children[]; };
// C++ mirror: layout::GpuWavefrontCounters.
layout(std430, binding = kWavefrontCounters) buffer Counters {
    uint child_count;
    uint finished_patches;
    uint split_patches;
    uint limited_patches;
    uint traced_rays;
    uint unused_counters[3];
};
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
uniform float min_power;      // share of a texel's unobstructed power below which a patch does not split
uniform int channel;          // −1: all channels at once; 0, 1, 2: this channel only (dispersion)
uniform vec3 power_unit;      // W per fixed-point tally unit, per channel

// The ray of emission square point u: from a cone's apex, by the concentric
// map onto the unit disk ([Shirley97]) and the disk onto the cap
// (1 − cos θ = r²(1 − cos α)), or from a directional light's disk. Both maps
// preserve area, so a patch's share of the emitter's power is its area in the
// square.
void emission_ray(Emitter emitter, vec2 u, out vec3 x, out vec3 d) {
    vec2 disk = sample_disk_concentric(u.x, u.y);
    if (emitter.origin.w == 0.0f) {
        float r2 = dot(disk, disk);
        float cos_theta = 1.0f - r2 * (1.0f - emitter.axis.w);
        float sin_theta = sqrt(max(0.0f, 1.0f - cos_theta * cos_theta));
        vec2 around = r2 > 0.0f ? disk / sqrt(r2) : vec2(1.0f, 0.0f);
        x = emitter.origin.xyz;
        d = normalize(cos_theta * emitter.axis.xyz + sin_theta * (around.x * emitter.tangent.xyz + around.y * emitter.bitangent.xyz));
    } else {
        x = emitter.origin.xyz + emitter.axis.w * (disk.x * emitter.tangent.xyz + disk.y * emitter.bitangent.xyz);
        d = emitter.axis.xyz;
    }
}

vec3 channel_mask() {
    if (channel < 0) return vec3(1.0f);
    vec3 only = vec3(0.0f);
    only[channel] = 1.0f;
    return only;
}

// Emitted power of the emitter per unit area of the emission square, where
// its spot profile is 1 (W, RGB).
vec3 emitter_power(Emitter emitter) { return emitter.photon_power.rgb * float(emitter.photons.y); }

// Where a step ended at a sharp surface: total internal reflection, or the
// transmitted light with its Fresnel transmittance.
void follow_transmitted(SurfaceCrossing crossing, INOUT(vec3) x, INOUT(vec3) x_lost, INOUT(vec3) v,
                        INOUT(vec4) field, INOUT(vec3) power, INOUT(uint) transmissions, INOUT(uint) reflections) {
    vec3 d = normalize(v);
    SurfaceEvent event = sharp_surface_event(crossing, x, d, inside_mask, channel_scale);
    x_lost = vec3(0.0f);
    if (event.reflectance >= 1.0f) {
        x = event.x_reflected;
        d = mirrored_direction(d, event.facing);
        ++reflections;
    } else {
        x = event.x_transmitted;
        d = refracted_direction(d, event.facing, event.n_here, event.n_beyond);
        power *= 1.0f - event.reflectance;
        inside_mask = event.beyond_mask;
        sharp_offset = event.beyond_offset;
        ++transmissions;
    }
    field = field_at(x);
    v = field.w * d;
}

void add_steps(uint steps, float max_invariant_error, float invariant_error_sum) {
    uint before = atomicAdd(step_tallies[0], steps);
    if (before + steps < before) atomicAdd(step_tallies[1], 1u);
    atomicMax(step_tallies[2], floatBitsToUint(max_invariant_error));
    atomicAdd(invariant_sum[0], invariant_error_sum);
}

// Traces the ray of emission square point u of `emitter_index` to its end.
Corner trace_corner(uint emitter_index, vec2 u) {
    Emitter emitter = emitters[emitter_index];
    vec3 x;
    vec3 direction;
    emission_ray(emitter, u, x, direction);
    channel_scale = channel < 0 ? dispersion.x : dispersion[channel];
    vec3 power = spot_profile(emitter, direction) * channel_mask();
    vec3 absorbed = vec3(0.0f);
    vec3 x_lost = vec3(0.0f);
#if EIKON_SHARP_SURFACES
    inside_mask = 0u;
    sharp_offset = 0.0f;
    if (grid_contains(x)) enter_sharp_region(x);
#endif
    vec4 field = grid_contains(x) ? field_at(x) : vec4(0.0f, 0.0f, 0.0f, reference_index());
    vec3 v = field.w * direction;
    uint steps = 0u;
    uint transmissions = 0u;
    uint reflections = 0u;
    float max_invariant_error = 0.0f;
    float invariant_error_sum = 0.0f;
    int fate = kEscaped;
    ReceiverHit landed = ReceiverHit(-1, 0.0f, false, vec2(0.0f));
    for (;;) {
        spend_loops(loops_per_pass());
        if (!loops_left()) {
            fate = kCutOff;
            break;
        }
        if (!grid_contains(x)) {
            vec3 d = normalize(v);
            StraightFlight flight = fly_straight(x, d);
            if (flight.hit.receiver >= 0) {
                landed = flight.hit;
                break;
            }
            if (!flight.enters_grid) break;
            x = grid_entry_point(x, d, flight);
            x_lost = vec3(0.0f);
            if (!grid_contains(x)) continue;
#if EIKON_SHARP_SURFACES
            enter_sharp_region(x);
#endif
            field = field_at(x);
            v = field.w * d;
            continue;
        }
        if (steps >= max_steps) {
            fate = kCutOff;
            break;
        }
        float ds = next_step(x, v);
#if EIKON_SHARP_SURFACES
        SurfaceCrossing crossing = nearest_surface_crossing(x, normalize(v), inside_mask, ds, 1e-4f * grid.voxel_size.x);
        ds = crossing.distance;
        if (!loops_left()) {
            fate = kCutOff;
            break;
        }
#endif
        vec3 start = x;
        integrate(x, x_lost, v, field, ds);
        ++steps;
        float invariant_error = eikonal_invariant_error(v, field.w);
        max_invariant_error = max(max_invariant_error, invariant_error);
        invariant_error_sum += invariant_error;
        ReceiverHit hit = first_receiver_crossing(start, x);
        vec3 transmitted = power * beer_lambert_transmittance(sample_extinction(start), hit.receiver >= 0 ? hit.fraction * ds : ds);
        absorbed += power - transmitted;
        power = transmitted;
        if (hit.receiver >= 0) {
            landed = hit;
            break;
        }
#if EIKON_SHARP_SURFACES
        if (crossing.surface >= 0) follow_transmitted(crossing, x, x_lost, v, field, power, transmissions, reflections);
#endif
        if (!grid_contains(x)) v = reference_index() * normalize(v);
    }
    if (landed.receiver >= 0) fate = landed.lit_side ? kReceived : kBlocked;
    add_steps(steps, max_invariant_error, invariant_error_sum);
    atomicAdd(traced_rays, 1u);
    Corner corner;
    corner.ends = vec4(u, landed.map_uv);
    corner.power = vec4(power, uintBitsToFloat(min(transmissions, 4095u) | (min(reflections, 4095u) << 12)));
    corner.absorbed = vec4(absorbed, uintBitsToFloat(uint(fate) | (uint(landed.receiver + 1) << 4)));
    return corner;
}

uint corner_history(Corner corner) { return floatBitsToUint(corner.power.w); }
uint corner_fate_code(Corner corner) { return floatBitsToUint(corner.absorbed.w); }
int corner_fate(Corner corner) { return int(corner_fate_code(corner) & 15u); }
int corner_receiver(Corner corner) { return int(corner_fate_code(corner) >> 4) - 1; }

// ---- fixed-point tallies (64-bit, two words with carry) ----

// A non-negative number of units as (low, high) words.
uvec2 wide_units(float units) {
    float high = floor(units / 4294967296.0f);
    float low = min(units - high * 4294967296.0f + 0.5f, 4294967040.0f);
    return uvec2(uint(max(low, 0.0f)), uint(high));
}

void add_stat(int tally, vec3 watts) {
    for (int c = 0; c < 3; ++c) {
        uvec2 value = wide_units(watts[c] / power_unit[c]);
        uint low_word = uint(2 * (3 * tally + c));
        if (value.x != 0u) {
            uint before = atomicAdd(power_tallies[low_word], value.x);
            if (before + value.x < before) atomicAdd(power_tallies[low_word + 1u], 1u);
        }
        if (value.y != 0u) atomicAdd(power_tallies[low_word + 1u], value.y);
    }
}

void deposit_in_texel(int r, ivec2 texel, vec3 watts) {
    uint resolution = receivers[r].map.y;
    uint base = 6u * (receivers[r].map.x + uint(texel.y) * resolution + uint(texel.x));
    for (int c = 0; c < 3; ++c) {
        uvec2 value = wide_units(watts[c] / power_unit[c]);
        uint low_word = base + uint(2 * c);
        if (value.x != 0u) {
            uint before = atomicAdd(receiver_tallies[low_word], value.x);
            if (before + value.x < before) atomicAdd(receiver_tallies[low_word + 1u], 1u);
        }
        if (value.y != 0u) atomicAdd(receiver_tallies[low_word + 1u], value.y);
    }
}

ivec2 texel_of(int r, vec2 map_uv) {
    int resolution = int(receivers[r].map.y);
    return clamp(ivec2(map_uv * float(resolution)), ivec2(0), ivec2(resolution - 1));
}

// Largest footprint, in texels of its bounding box, spread by coverage; a
// larger one (only patches at the limit) is deposited at its corners.
const int kMaxFootprintTexels = 256;

// The patch's power `watts`, arriving on receiver r over the triangle of map
// coordinates (a, b, c), into the texels it covers by their share of its area.
void deposit_footprint(int r, vec2 a, vec2 b, vec2 c, vec3 watts) {
    float resolution = float(receivers[r].map.y);
    vec2 lowest = floor(min(a, min(b, c)) * resolution);
    vec2 ta = a * resolution - lowest;  // texel coordinates from the footprint's first texel
    vec2 tb = b * resolution - lowest;
    vec2 tc = c * resolution - lowest;
    ivec2 span = ivec2(floor(max(ta, max(tb, tc)))) + 1;
    float area = 0.5f * abs(twice_signed_area(ta, tb, tc));
    if (area <= 1e-12f || span.x * span.y == 1) {
        deposit_in_texel(r, texel_of(r, (a + b + c) / 3.0f), watts);
        return;
    }
    if (span.x * span.y > kMaxFootprintTexels) {
        deposit_in_texel(r, texel_of(r, a), watts / 3.0f);
        deposit_in_texel(r, texel_of(r, b), watts / 3.0f);
        deposit_in_texel(r, texel_of(r, c), watts / 3.0f);
        return;
    }
    spend_loops(uint(span.x * span.y));
    ivec2 first = ivec2(lowest);
    int last = int(resolution) - 1;
    for (int j = 0; j < span.y; ++j)
        for (int i = 0; i < span.x; ++i) {
            float covered = triangle_texel_coverage(ta, tb, tc, vec2(float(i), float(j)));
            if (covered > 0.0f) deposit_in_texel(r, min(first + ivec2(i, j), ivec2(last)), watts * (covered / area));
        }
}

// A patch that is done: its power Φ = (emitter power density) × (area in the
// emission square), a third to each corner's ledger — emitted, absorbed,
// its fate, unfollowed reflections — and onto its receiver: by footprint
// when all corners agree, else each corner's third at its own texel.
void finish_patch(Patch p, bool agreed) {
    Emitter emitter = emitters[p.info.x];
    vec2 u0 = p.corners[0].ends.xy;
    vec2 u1 = p.corners[1].ends.xy;
    vec2 u2 = p.corners[2].ends.xy;
    vec3 third = emitter_power(emitter) * (0.5f * abs(twice_signed_area(u0, u1, u2)) / 3.0f);
    vec3 emitted = vec3(0.0f);
    vec3 absorbed = vec3(0.0f);
    vec3 unfollowed = vec3(0.0f);
    vec3 arriving = vec3(0.0f);
    for (int k = 0; k < 3; ++k) {
        Corner corner = p.corners[k];
        vec3 sent = channel_mask();
        if (emitter.spot.w >= -1.5f) {  // a spot light: its profile at the corner
            vec3 x;
            vec3 d;
            emission_ray(emitter, corner.ends.xy, x, d);
            sent *= spot_profile(emitter, d);
        }
        emitted += third * sent;
        absorbed += third * corner.absorbed.rgb;
        unfollowed += third * max(sent - corner.power.rgb - corner.absorbed.rgb, vec3(0.0f));
        arriving += third * corner.power.rgb;
        int fate = corner_fate(corner);
        if (!agreed) {
            add_stat(fate, third * corner.power.rgb);
            if (fate == kReceived) deposit_in_texel(corner_receiver(corner), texel_of(corner_receiver(corner), corner.ends.zw),
                                                    third * corner.power.rgb);
        }
    }
    add_stat(kEmitted, emitted);
    add_stat(kAbsorbed, absorbed);
    add_stat(kUnfollowed, unfollowed);
    if (agreed) {
        int fate = corner_fate(p.corners[0]);
        add_stat(fate, arriving);
        if (fate == kReceived)
            deposit_footprint(corner_receiver(p.corners[0]), p.corners[0].ends.zw, p.corners[1].ends.zw,
                              p.corners[2].ends.zw, arriving);
    }
    atomicAdd(finished_patches, 1u);
}

bool corners_agree(Patch p) {
    return corner_history(p.corners[0]) == corner_history(p.corners[1]) &&
           corner_history(p.corners[1]) == corner_history(p.corners[2]) &&
           corner_fate_code(p.corners[0]) == corner_fate_code(p.corners[1]) &&
           corner_fate_code(p.corners[1]) == corner_fate_code(p.corners[2]);
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
        emission_ray(emitter, p.corners[k].ends.xy, x, d);
        float t = receiver_ray_parameter(x, d, receiver.origin.xyz, receiver.normal.xyz);
        if (t < 0.0f) return false;
        ends[k] = receiver_map_coordinates(x + t * d, receiver.origin.xyz, receiver.axis_u.xyz, receiver.axis_v.xyz,
                                           receiver.origin.w) * float(receiver.map.y);
    }
    return true;
}

float longest_edge(vec2 a, vec2 b, vec2 c) { return max(distance(a, b), max(distance(b, c), distance(c, a))); }

// Whether a patch must split.
// - Corners agree, on a receiver: while its footprint has an edge longer than
//   split_texels, unless it carries less than min_power of what a texel
//   there gets unobstructed (the light a grazing ray refracts into a wide,
//   faint halo, which would otherwise split without end; what such a patch
//   misplaces is at most its own power).
// - Corners disagree (a shadow edge, a tear of the wavefront at a silhouette
//   or where total internal reflection sets in): while its straight
//   footprint on the receiver a corner reached is larger than tear_texels.
//   Disagreeing corners none of which reached a receiver deposit nothing:
//   the patch stops.
bool wants_split(Patch p, bool agreed) {
    int r = -1;
    for (int k = 2; k >= 0; --k)
        if (corner_fate(p.corners[k]) == kReceived) r = corner_receiver(p.corners[k]);
    if (r < 0) return false;
    vec2 straight[3];
    bool ahead = straight_footprint(p, r, straight);
    if (!agreed) return !ahead || longest_edge(straight[0], straight[1], straight[2]) > tear_texels;
    float resolution = float(receivers[r].map.y);
    if (longest_edge(p.corners[0].ends.zw * resolution, p.corners[1].ends.zw * resolution,
                     p.corners[2].ends.zw * resolution) <= split_texels)
        return false;
    if (!ahead) return true;
    vec3 arriving = p.corners[0].power.rgb + p.corners[1].power.rgb + p.corners[2].power.rgb;
    float share = max(arriving.r, max(arriving.g, arriving.b)) / 3.0f;
    return share * 0.5f * abs(twice_signed_area(straight[0], straight[1], straight[2])) >= min_power;
}

// A child patch whose corners are the parent's corners or, still to be
// traced (mode 1), edge midpoints of the emission square.
Corner untraced_corner(vec2 u) {
    Corner corner;
    corner.ends = vec4(u, 0.0f, 0.0f);
    corner.power = vec4(0.0f);
    corner.absorbed = vec4(0.0f);
    return corner;
}

void write_child(uint slot, uint emitter, uint depth, Corner a, Corner b, Corner c) {
    children[slot].corners[0] = a;
    children[slot].corners[1] = b;
    children[slot].corners[2] = c;
    children[slot].info = uvec4(emitter, depth, 0u, 0u);
}

// The four children of p at slot…slot + 3: its corners and its three edge
// midpoints m01, m12, m20 — as (c0, m01, m20), (m01, c1, m12),
// (m20, m12, c2), (m01, m12, m20) — the midpoints traced by mode 1.
void split_patch(Patch p, uint slot) {
    uint emitter = p.info.x;
    Corner m01 = untraced_corner(0.5f * (p.corners[0].ends.xy + p.corners[1].ends.xy));
    Corner m12 = untraced_corner(0.5f * (p.corners[1].ends.xy + p.corners[2].ends.xy));
    Corner m20 = untraced_corner(0.5f * (p.corners[2].ends.xy + p.corners[0].ends.xy));
    uint depth = p.info.y + 1u;
    write_child(slot + 0u, emitter, depth, p.corners[0], m01, m20);
    write_child(slot + 1u, emitter, depth, m01, p.corners[1], m12);
    write_child(slot + 2u, emitter, depth, m20, m12, p.corners[2]);
    write_child(slot + 3u, emitter, depth, m01, m12, m20);
    atomicAdd(split_patches, 1u);
}

// Mode 2: patch `index` of the level finishes, or splits into Children.
void refine(uint index) {
    Patch p = patches[index];
    bool agreed = corners_agree(p);
    bool splitting = wants_split(p, agreed);
    if (splitting && p.info.y < max_depth) {
        uint slot = atomicAdd(child_count, 4u);
        if (slot + 4u <= capacity) {
            split_patch(p, slot);
            return;
        }
    }
    if (splitting) atomicAdd(limited_patches, 1u);
    finish_patch(p, agreed);
}

// Mode 0: seed patch `index` of this chunk, half of cell first_cell + index / 2
// of the emission square's grid_cells² cells, its corners to be traced.
void seed(uint index) {
    uint cell = first_cell + index / 2u;
    vec2 low = vec2(float(cell % grid_cells), float(cell / grid_cells)) / float(grid_cells);
    float size = 1.0f / float(grid_cells);
    vec2 other = (index % 2u == 0u) ? low + vec2(size, 0.0f) : low + vec2(0.0f, size);
    write_child(index, seed_emitter, 0u, untraced_corner(low), untraced_corner(other), untraced_corner(low + vec2(size)));
}

// Mode 1: ray `job` of the children. After seeding, corner job % 3 of patch
// job / 3; after a split, midpoint job % 3 (m01, m12, m20) of the four
// children at 4·(job / 3), written to each child that has it.
void trace_job(uint job) {
    uint which = job % 3u;
    uint first = job / 3u;
    if (seeded_jobs != 0u) {
        children[first].corners[which] = trace_corner(children[first].info.x, children[first].corners[which].ends.xy);
        return;
    }
    uint slot = 4u * first;
    if (which == 0u) {  // m01: child 0 corner 1, child 1 corner 0, child 3 corner 0
        Corner m = trace_corner(children[slot].info.x, children[slot].corners[1].ends.xy);
        children[slot].corners[1] = m;
        children[slot + 1u].corners[0] = m;
        children[slot + 3u].corners[0] = m;
    } else if (which == 1u) {  // m12: child 1 corner 2, child 2 corner 1, child 3 corner 1
        Corner m = trace_corner(children[slot].info.x, children[slot + 1u].corners[2].ends.xy);
        children[slot + 1u].corners[2] = m;
        children[slot + 2u].corners[1] = m;
        children[slot + 3u].corners[1] = m;
    } else {  // m20: child 0 corner 2, child 2 corner 0, child 3 corner 2
        Corner m = trace_corner(children[slot].info.x, children[slot].corners[2].ends.xy);
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
