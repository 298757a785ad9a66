// Wavefront pass: adaptive wavefront tracing ([Ihrke07] §4.2 and §5.2,
// after Enquist and Runborg). A light's emission square (common/emitters.glsl:
// the directions of a point or spot light toward the traced region, the
// positions of a directional light's disk) is cut into triangular patches
// whose corners are rays, traced with the photons' march
// (common/ray_march.glsl) through the graded field and its sharp surfaces,
// deterministically: at a sharp surface a ray follows one branch of the
// Fresnel ray tree with that branch's transmittance or reflectance as its
// power factor (the main wavefront transmits; branch wavefronts reflect once,
// at their own Fresnel event; total internal reflection always reflects);
// what no wavefront follows is tallied as unfollowed. A patch whose corners disagree in
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
    vec4 source;    // rgb: power the ray starts this wavefront with (emitted, or reflected into the branch)
};
struct Patch {
    Corner corners[3];
    uvec4 info;  // x: emitter, y: depth, z: face of the emission domain
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
uniform int branch;           // −1: the main wavefront; b: the branch reflected at Fresnel event b
const uint kUnbranched = 0xFFFFFFu;  // history of a ray that ended before its branch's reflection
uniform vec3 power_unit;      // W per fixed-point tally unit, per channel

uniform uint emission_faces;  // faces of this emitter's emission domain (WavefrontStage::emissionFaces)

// The emission domain of a light: one or six square faces, each [0, 1]², so
// that straight lines in a face stay straight where light lands on a plane
// (a patch's footprint there is the triangle of its corners) and a patch's
// power is exact:
// - a directional light: the square circumscribing its disk, positions
//   origin + R·((2u − 1)·tangent + (2v − 1)·bitangent); power E·area;
// - a point or spot light whose cone toward the traced region is at most 60°
//   wide: the gnomonic square of that cone, directions axis +
//   tan α·((2u − 1)·tangent + (2v − 1)·bitangent), normalised; power I·Ω,
//   Ω the solid angle of the spherical triangle of the corner directions
//   (great circles are the gnomonic images of straight lines);
// - a wider cone: the six faces of the cube about the light (face k: ±axis,
//   ±tangent, ±bitangent), each gnomonic.
vec3 face_direction(Emitter emitter, uint face, vec2 u) {
    vec2 s = 2.0f * u - 1.0f;
    vec3 axis = emitter.axis.xyz;
    vec3 tangent = emitter.tangent.xyz;
    vec3 bitangent = emitter.bitangent.xyz;
    if (emission_faces == 1u) {
        float spread = sqrt(max(0.0f, 1.0f - emitter.axis.w * emitter.axis.w)) / emitter.axis.w;  // tan α
        return axis + spread * (s.x * tangent + s.y * bitangent);
    }
    float side = (face % 2u == 0u) ? 1.0f : -1.0f;
    if (face < 2u) return side * axis + s.x * tangent + s.y * bitangent;
    if (face < 4u) return side * tangent + s.x * bitangent + s.y * axis;
    return side * bitangent + s.x * axis + s.y * tangent;
}

void emission_ray(Emitter emitter, uint face, vec2 u, out vec3 x, out vec3 d) {
    if (emitter.origin.w == 0.0f) {
        x = emitter.origin.xyz;
        d = normalize(face_direction(emitter, face, u));
    } else {
        vec2 s = 2.0f * u - 1.0f;
        x = emitter.origin.xyz + emitter.axis.w * (s.x * emitter.tangent.xyz + s.y * emitter.bitangent.xyz);
        d = emitter.axis.xyz;
    }
}

vec3 channel_mask() {
    if (channel < 0) return vec3(1.0f);
    vec3 only = vec3(0.0f);
    only[channel] = 1.0f;
    return only;
}

// The power (W, RGB, where the spot profile is 1) a patch of face `face`
// with corners u0, u1, u2 receives from the emitter: the photon emitter's
// power over its cone or disk (photon power × photons) gives the intensity
// I = P/(2π(1 − cos α)) or irradiance E = P/(πR²). The solid angle is
// Van Oosterom and Strackee's, tan(Ω/2) = |a·(b×c)| / (1 + a·b + b·c + c·a),
// in double precision: a patch a ten-thousandth of a radian across would
// lose three digits in float.
vec3 patch_power(Emitter emitter, uint face, vec2 u0, vec2 u1, vec2 u2) {
    vec3 power = emitter.photon_power.rgb * float(emitter.photons.y);
    if (emitter.origin.w != 0.0f) {
        float radius = emitter.axis.w;
        return power / (3.14159265358979f * radius * radius) * (4.0f * radius * radius) *
               (0.5f * abs(twice_signed_area(u0, u1, u2)));
    }
    dvec3 a = normalize(dvec3(face_direction(emitter, face, u0)));
    dvec3 b = normalize(dvec3(face_direction(emitter, face, u1)));
    dvec3 c = normalize(dvec3(face_direction(emitter, face, u2)));
    double triple = abs(dot(a, cross(b - a, c - a)));
    double denominator = 1.0lf + dot(a, b) + dot(b, c) + dot(c, a);
    float solid_angle = 2.0f * atan(float(triple), float(denominator));
    float cone = 2.0f * 3.14159265358979f * (1.0f - emitter.axis.w);
    return power / cone * solid_angle;
}

// A ray's ledger at sharp surfaces. A Fresnel event is a crossing whose
// reflectance is strictly between 0 and 1 (total internal reflection is not
// one: it always reflects). Each wavefront follows one branch of the ray
// tree: the main one (`branch` −1) transmits at every Fresnel event; branch
// b reflects at Fresnel event b and transmits at the others. What a branch
// does not follow is tallied as unfollowed; the power a branch starts with
// at its reflection is its source.
struct SurfaceLedger {
    uint transmissions;
    uint reflections;  // total internal reflections, and the branch's own
    uint fresnel_events;
    bool branched;     // the branch's reflection has happened (always true for the main branch)
};

#if EIKON_SHARP_SURFACES
// Where a step ended at a sharp surface: the way this wavefront's branch goes
// on, with the Fresnel transmittance or reflectance as its power factor.
void follow_branch(SurfaceCrossing crossing, INOUT(vec3) x, INOUT(vec3) x_lost, INOUT(vec3) v, INOUT(vec4) field,
                   INOUT(vec3) power, INOUT(vec3) absorbed, INOUT(vec3) source, INOUT(SurfaceLedger) ledger) {
    vec3 d = normalize(v);
    SurfaceEvent event = sharp_surface_event(crossing, x, d, inside_mask, channel_scale);
    x_lost = vec3(0.0f);
    bool fresnel_event = event.reflectance > 0.0f && event.reflectance < 1.0f;
    bool reflects = event.reflectance >= 1.0f || (fresnel_event && int(ledger.fresnel_events) == branch);
    if (fresnel_event) ++ledger.fresnel_events;
    if (reflects) {
        x = event.x_reflected;
        d = mirrored_direction(d, event.facing);
        ++ledger.reflections;
        if (event.reflectance < 1.0f) {  // this branch's reflection: its ledger starts here
            power *= event.reflectance;
            source = power;
            absorbed = vec3(0.0f);
            ledger.branched = true;
        }
    } else {
        x = event.x_transmitted;
        d = refracted_direction(d, event.facing, event.n_here, event.n_beyond);
        power *= 1.0f - event.reflectance;
        inside_mask = event.beyond_mask;
        sharp_offset = event.beyond_offset;
        ++ledger.transmissions;
    }
    field = field_at(x);
    v = field.w * d;
}
#endif

void add_steps(uint steps, float max_invariant_error, float invariant_error_sum) {
    uint before = atomicAdd(step_tallies[0], steps);
    if (before + steps < before) atomicAdd(step_tallies[1], 1u);
    atomicMax(step_tallies[2], floatBitsToUint(max_invariant_error));
    atomicAdd(invariant_sum[0], invariant_error_sum);
}

// Where a ray first crossed a receiver's plane outside its square: a
// footprint reaching past the square's edge is cut there exactly.
struct PlaneCrossing {
    int receiver;  // −1: none yet
    vec2 map_uv;
};

void note_plane_crossing(vec3 a, vec3 b, INOUT(PlaneCrossing) crossing) {
    if (crossing.receiver >= 0) return;
    for (uint r = 0u; r < receiver_count; ++r) {
        float da = receiver_signed_distance(a, receivers[r].origin.xyz, receivers[r].normal.xyz);
        float db = receiver_signed_distance(b, receivers[r].origin.xyz, receivers[r].normal.xyz);
        if (!(da > 0.0f && db <= 0.0f)) continue;  // lit side to back only
        crossing.receiver = int(r);
        crossing.map_uv = receiver_map_coordinates(mix(a, b, da / (da - db)), receivers[r].origin.xyz,
                                                   receivers[r].axis_u.xyz, receivers[r].axis_v.xyz,
                                                   receivers[r].origin.w);
        return;
    }
}

// Traces the ray of point u of face `face` of the emitter's domain to its end.
Corner trace_corner(uint emitter_index, uint face, vec2 u) {
    Emitter emitter = emitters[emitter_index];
    vec3 x;
    vec3 direction;
    emission_ray(emitter, face, u, x, direction);
    PlaneCrossing outside = PlaneCrossing(-1, vec2(0.0f));
    channel_scale = channel < 0 ? dispersion.x : dispersion[channel];
    vec3 power = spot_profile(emitter, direction) * channel_mask();
    vec3 source = branch < 0 ? power : vec3(0.0f);
    vec3 absorbed = vec3(0.0f);
    SurfaceLedger ledger = SurfaceLedger(0u, 0u, 0u, branch < 0);
    vec3 x_lost = vec3(0.0f);
#if EIKON_SHARP_SURFACES
    inside_mask = 0u;
    sharp_offset = 0.0f;
    if (grid_contains(x)) enter_sharp_region(x);
#endif
    vec4 field = grid_contains(x) ? field_at(x) : vec4(0.0f, 0.0f, 0.0f, reference_index());
    vec3 v = field.w * direction;
    uint steps = 0u;
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
            note_plane_crossing(x, x + flight.distance * d, outside);
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
        note_plane_crossing(start, x, outside);
#if EIKON_SHARP_SURFACES
        if (crossing.surface >= 0) follow_branch(crossing, x, x_lost, v, field, power, absorbed, source, ledger);
#endif
        if (!grid_contains(x)) v = reference_index() * normalize(v);
    }
    if (landed.receiver >= 0) fate = landed.lit_side ? kReceived : kBlocked;
    if (fate == kEscaped && outside.receiver >= 0) {  // escaped past a square: where it crossed its plane
        landed.receiver = outside.receiver;
        landed.map_uv = outside.map_uv;
    }
    add_steps(steps, max_invariant_error, invariant_error_sum);
    atomicAdd(traced_rays, 1u);
    Corner corner;
    corner.ends = vec4(u, landed.map_uv);
    uint history = min(ledger.transmissions, 4095u) | (min(ledger.reflections, 4095u) << 12);
    if (!ledger.branched) {  // the ray ended before this branch's reflection: none of its power is here
        power = vec3(0.0f);
        absorbed = vec3(0.0f);
        history = kUnbranched;
        fate = kEscaped;
        landed.receiver = -1;
    }
    corner.power = vec4(power, uintBitsToFloat(history));
    corner.absorbed = vec4(absorbed, uintBitsToFloat(uint(fate) | (uint(landed.receiver + 1) << 4)));
    corner.source = vec4(source, 0.0f);
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

bool on_square(vec2 map_uv) { return all(greaterThanEqual(map_uv, vec2(0.0f))) && all(lessThan(map_uv, vec2(1.0f))); }

// Largest footprint, in texels of its bounding box on the map, spread by
// coverage; a larger one (only patches at the limit) is deposited at its
// corners.
const int kMaxFootprintTexels = 256;

// The patch's power `watts`, arriving in receiver r's plane over the
// triangle of map coordinates (a, b, c), into the texels of the square it
// covers by their share of its area; returns the share of `watts` that fell
// on the square (the rest passed its edge).
float deposit_footprint(int r, vec2 a, vec2 b, vec2 c, vec3 watts) {
    float resolution = float(receivers[r].map.y);
    vec2 ta = a * resolution;
    vec2 tb = b * resolution;
    vec2 tc = c * resolution;
    vec2 first = max(floor(min(ta, min(tb, tc))), vec2(0.0f));
    vec2 last = min(floor(max(ta, max(tb, tc))), vec2(resolution - 1.0f));
    if (any(greaterThan(first, last))) return 0.0f;  // wholly beside the square
    float area = 0.5f * abs(twice_signed_area(ta, tb, tc));
    ivec2 span = ivec2(last - first) + 1;
    if (area <= 1e-12f) {  // folded to a line or a point: at the centroid
        vec2 middle = (a + b + c) / 3.0f;
        if (!on_square(middle)) return 0.0f;
        deposit_in_texel(r, texel_of(r, middle), watts);
        return 1.0f;
    }
    if (span.x * span.y > kMaxFootprintTexels) {
        float share = 0.0f;
        vec2 corners[3] = vec2[3](a, b, c);
        for (int k = 0; k < 3; ++k)
            if (on_square(corners[k])) {
                deposit_in_texel(r, texel_of(r, corners[k]), watts / 3.0f);
                share += 1.0f / 3.0f;
            }
        return share;
    }
    spend_loops(uint(span.x * span.y));
    ta -= first;  // coordinates from the first texel, for precision
    tb -= first;
    tc -= first;
    float covered_sum = 0.0f;
    for (int j = 0; j < span.y; ++j)
        for (int i = 0; i < span.x; ++i) {
            float covered = triangle_texel_coverage(ta, tb, tc, vec2(float(i), float(j)));
            if (covered <= 0.0f) continue;
            deposit_in_texel(r, ivec2(first) + ivec2(i, j), watts * (covered / area));
            covered_sum += covered;
        }
    return min(covered_sum / area, 1.0f);
}

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

// A patch that is done: its power Φ (patch_power), a third to each corner's
// ledger — its source, absorbed, unfollowed reflections — and what arrives:
// on a receiver's plane, by footprint (the part on the square received, the
// rest escaped); with corners that agree elsewhere, to their common fate;
// else each corner's third to its own fate, at its own texel if received.
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

// Whether a patch carries at least min_power of what a texel gets where its
// straight footprint lies (its corners' power over the straight footprint's
// area in texels): splitting a fainter one cannot move much light.
bool carries_power(Patch p, vec2 straight[3]) {
    vec3 arriving = p.corners[0].power.rgb + p.corners[1].power.rgb + p.corners[2].power.rgb;
    float share = max(arriving.r, max(arriving.g, arriving.b)) / 3.0f;
    return share * 0.5f * abs(twice_signed_area(straight[0], straight[1], straight[2])) >= min_power;
}

// Whether a patch must split: while it is larger than split_texels on a
// receiver and carries power (carries_power) — the light a grazing ray
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
bool wants_split(Patch p) {
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

// A child patch whose corners are the parent's corners or, still to be
// traced (mode 1), edge midpoints of the emission square.
Corner untraced_corner(vec2 u) {
    Corner corner;
    corner.ends = vec4(u, 0.0f, 0.0f);
    corner.power = vec4(0.0f);
    corner.absorbed = vec4(0.0f);
    corner.source = vec4(0.0f);
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
