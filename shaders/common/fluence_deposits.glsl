// Fluence in the grid, shared by the photon pass (photon_trace.comp) and the
// wavefront pass (wavefront_trace.comp): the raw tallies a light pass adds to
// — fluence φ (W/m²) and its power-weighted direction per cell, and, for the
// multiple-scattering lattice, the power scattered per cell — and the two
// ways to fill them (docs/architecture.md, Conventions: φ = Σ Φ·ℓ / h³):
//   deposit_segment       a photon's path, by the track length in each voxel
//                         it crosses (3D DDA, [Amanatides87]);
//   deposit_tube_segment  the axis of a wavefront tube narrower than a voxel,
//                         by smooth cloud weights, so that tubes whose axes
//                         fall anywhere in a voxel give it a smooth share
//                         instead of all or nothing.
// Includes grid_sampling.glsl, loop_budget.glsl and attenuation.glsl first,
// and wide_units.glsl itself. GLSL only.
//
// Program options (#defines set by the stage):
//   EIKON_STORE_FLUENCE    0 none, 1 where σs > 0, 2 everywhere
//   EIKON_LATTICE_SOURCE   1: also the power scattered per cell (the multiple-scattering lattice's source)
//   EIKON_FIXED_FLUENCE    1: the tallies are 64-bit fixed point (the wavefront's: integer sums do not
//                          depend on the order deposits arrive in, so a relight gives the same bits),
//                          converted to floats by fluence_smooth.comp; 0: float sums (photons')
#ifndef EIKON_STORE_FLUENCE
#define EIKON_STORE_FLUENCE 0
#endif
#ifndef EIKON_LATTICE_SOURCE
#define EIKON_LATTICE_SOURCE 0
#endif
#ifndef EIKON_FIXED_FLUENCE
#define EIKON_FIXED_FLUENCE 0
#endif

#include "common/wide_units.glsl"

#if EIKON_STORE_FLUENCE > 0
#if EIKON_FIXED_FLUENCE
// Per cell and channel (axis) a 64-bit sum as (low, high) words: track
// length in units of fluence_unit (W·m) per channel, the power-weighted
// direction (two's complement) in units of direction_unit, the scattered
// power in units of scattered_unit (W).
layout(std430, binding = kRawFluence) buffer RawFluence { uint raw_fluence[]; };
#if EIKON_LATTICE_SOURCE
layout(std430, binding = kRawScattered) buffer RawScattered { uint raw_scattered[]; };
#endif
layout(std430, binding = kRawFluenceDirection) buffer RawFluenceDirection { uint raw_fluence_direction[]; };
uniform vec3 fluence_unit;
uniform float direction_unit;
uniform vec3 scattered_unit;
#else
layout(std430, binding = kRawFluence) buffer RawFluence { float raw_fluence[]; };  // RGB per cell, W/m²
#if EIKON_LATTICE_SOURCE
layout(std430, binding = kRawScattered) buffer RawScattered { float raw_scattered[]; };  // RGB per cell, W
#endif
layout(std430, binding = kRawFluenceDirection) buffer RawFluenceDirection { float raw_fluence_direction[]; };  // xyz per cell
#endif
#endif

uint deposits = 0u;  // cells this invocation added fluence to

#if EIKON_STORE_FLUENCE > 0
// Whether cell keeps fluence: every cell, or (EIKON_STORE_FLUENCE 1) those
// that scatter, the only ones the view pass reads it in.
bool stores_fluence(ivec3 cell) {
#if EIKON_STORE_FLUENCE == 1
    return any(greaterThan(texelFetch(scattering_texture, cell, 0).rgb, vec3(0.0f)));
#else
    return true;
#endif
}

// `track` (W·m, per channel) spent in `cell` going along `direction`.
void add_fluence(ivec3 cell, vec3 track, vec3 direction) {
    if (!stores_fluence(cell)) return;
#if EIKON_FIXED_FLUENCE
    uint words = 6u * uint(grid_linear_index(cell));
    vec3 weighted = (track.r + track.g + track.b) * direction / direction_unit;
    for (int c = 0; c < 3; ++c) {
        ADD_WIDE_UNITS(raw_fluence, words + uint(2 * c), wide_units(track[c] / fluence_unit[c]));
        ADD_WIDE_UNITS(raw_fluence_direction, words + uint(2 * c), signed_wide_units(weighted[c]));
    }
    ++deposits;
#else
    uint index = 3u * uint(grid_linear_index(cell));
    vec3 value = track / grid.voxel_size.w;
    atomicAdd(raw_fluence[index + 0u], value.r);
    atomicAdd(raw_fluence[index + 1u], value.g);
    atomicAdd(raw_fluence[index + 2u], value.b);
    vec3 weighted = (value.r + value.g + value.b) * direction;
    atomicAdd(raw_fluence_direction[index + 0u], weighted.x);
    atomicAdd(raw_fluence_direction[index + 1u], weighted.y);
    atomicAdd(raw_fluence_direction[index + 2u], weighted.z);
    ++deposits;
#endif
}
#endif

// The power scattered out of a track in `cell`, by the σs/κ of the step's
// start that its attenuation used: the lattice's source.
void add_scattered(ivec3 cell, vec3 track, vec3 sigma_s) {
#if EIKON_STORE_FLUENCE > 0 && EIKON_LATTICE_SOURCE
    vec3 scattered = track * sigma_s;
    if (!any(greaterThan(scattered, vec3(0.0f)))) return;
#if EIKON_FIXED_FLUENCE
    uint words = 6u * uint(grid_linear_index(cell));
    for (int c = 0; c < 3; ++c)
        ADD_WIDE_UNITS(raw_scattered, words + uint(2 * c), wide_units(scattered[c] / scattered_unit[c]));
#else
    uint index = 3u * uint(grid_linear_index(cell));
    atomicAdd(raw_scattered[index + 0u], scattered.r);
    atomicAdd(raw_scattered[index + 1u], scattered.g);
    atomicAdd(raw_scattered[index + 2u], scattered.b);
#endif
#endif
}

// The power-weighted length (W·m) of a piece `piece` long that starts
// `travelled` along a segment entered with `power` at extinction κ: the
// power there times the length it spends decaying across the piece.
vec3 piece_track(vec3 power, vec3 kappa, float travelled, float piece) {
    return power * beer_lambert_transmittance(kappa, travelled) * attenuated_track_length(kappa, piece);
}

// Track-length estimator over the segment a → b: a 3D DDA visits every voxel
// the segment crosses and adds the power-weighted length spent in it, with
// Beer–Lambert decay along the way at the segment's extinction κ.
void deposit_segment(vec3 a, vec3 b, vec3 power, vec3 kappa, vec3 sigma_s) {
#if EIKON_STORE_FLUENCE > 0
    vec3 delta = b - a;
    float length_ = length(delta);
    if (length_ <= 0.0f) return;
    vec3 direction = delta / length_;
    vec3 p = (a - grid.bounds_min.xyz) / grid.voxel_size.xyz;
    vec3 q = (b - grid.bounds_min.xyz) / grid.voxel_size.xyz;
    vec3 span = q - p;
    ivec3 cell = clamp(ivec3(floor(p)), ivec3(0), grid.resolution.xyz - 1);
    ivec3 stride = ivec3(sign(span));
    vec3 inverse = 1.0f / abs(span);
    vec3 next_face = vec3(cell) + step(vec3(0.0f), span);  // the face ahead on each axis
    vec3 t_max = mix((next_face - p) / span, vec3(1e30f), equal(span, vec3(0.0f)));
    vec3 t_delta = mix(inverse, vec3(1e30f), equal(span, vec3(0.0f)));
    float t = 0.0f;
    int guard = 3 * (int(abs(span.x)) + int(abs(span.y)) + int(abs(span.z))) + 6;
    spend_loops(uint(guard));
    for (int i = 0; i < guard; ++i) {
        float t_next = min(1.0f, min(t_max.x, min(t_max.y, t_max.z)));
        float piece = (t_next - t) * length_;
        if (piece > 0.0f) {
            vec3 track = piece_track(power, kappa, t * length_, piece);
            add_fluence(cell, track, direction);
            add_scattered(cell, track, sigma_s);
        }
        if (t_next >= 1.0f) break;
        t = t_next;
        if (t_max.x <= t_max.y && t_max.x <= t_max.z) {
            cell.x += stride.x;
            t_max.x += t_delta.x;
        } else if (t_max.y <= t_max.z) {
            cell.y += stride.y;
            t_max.y += t_delta.y;
        } else {
            cell.z += stride.z;
            t_max.z += t_delta.z;
        }
        if (any(lessThan(cell, ivec3(0))) || any(greaterThanEqual(cell, grid.resolution.xyz))) break;
    }
#endif
}

// Cloud estimator over the segment a → b of a tube's axis carrying `power`:
// the segment is cut into pieces of at most half a voxel, and each piece's
// power-weighted length goes to the 27 cells about its midpoint by the
// quadratic B-spline weights between cell centres ("triangular-shaped
// cloud"; cells past the grid's faces fold onto the face cells, so nothing
// is lost). The weights sum to one: the track length, and so the energy in
// the grid, is the photons'; what changes is that a thin tube's light
// spreads over the cells its width could reach rather than landing in the
// one its axis crosses. The spline, not the trilinear tent: the tubes' axes
// sample the cross-section on the patches' lattice, and the ripple that
// sampling leaves falls with the kernel's spectrum, sinc³ against sinc² —
// about 1% with the tent at the default split_voxels, 0.1% with the spline.
// The power scattered goes to the cell the piece is in, as for photons.
void deposit_tube_segment(vec3 a, vec3 b, vec3 power, vec3 kappa, vec3 sigma_s) {
#if EIKON_STORE_FLUENCE > 0
    vec3 delta = b - a;
    float length_ = length(delta);
    if (length_ <= 0.0f) return;
    vec3 direction = delta / length_;
    vec3 p = (a - grid.bounds_min.xyz) / grid.voxel_size.xyz;
    vec3 span = (b - a) / grid.voxel_size.xyz;
    int pieces = max(1, int(ceil(2.0f * max(abs(span.x), max(abs(span.y), abs(span.z))))));
    spend_loops(uint(27 * pieces));
    float piece = length_ / float(pieces);
    for (int i = 0; i < pieces; ++i) {
        vec3 track = piece_track(power, kappa, float(i) * piece, piece);
        vec3 middle = p + (float(i) + 0.5f) / float(pieces) * span;
        add_scattered(clamp(ivec3(floor(middle)), ivec3(0), grid.resolution.xyz - 1), track, sigma_s);
        vec3 nearest = floor(middle);  // the cell whose centre is nearest
        vec3 d = middle - nearest - 0.5f;  // from that centre, in [−1/2, 1/2]
        vec3 below = 0.5f * (0.5f - d) * (0.5f - d);
        vec3 centre = 0.75f - d * d;
        vec3 above = 0.5f * (0.5f + d) * (0.5f + d);
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    ivec3 offset = ivec3(dx, dy, dz);
                    vec3 weights = mix(mix(below, centre, vec3(greaterThanEqual(offset, ivec3(0)))), above,
                                       vec3(greaterThan(offset, ivec3(0))));
                    ivec3 cell = clamp(ivec3(nearest) + offset, ivec3(0), grid.resolution.xyz - 1);
                    add_fluence(cell, track * (weights.x * weights.y * weights.z), direction);
                }
    }
#endif
}
