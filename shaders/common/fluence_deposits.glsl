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
// The tallies are GLSL only; the two ways to fill them are
// common/fluence_tracks.glsl, shared with C++. Includes grid_sampling.glsl,
// loop_budget.glsl and attenuation.glsl first, and wide_units.glsl itself.
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

#include "common/fluence_tracks.glsl"
