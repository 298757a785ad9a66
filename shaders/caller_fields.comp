// The library's GPU path (eikon::Field::buffer): a caller's fields in GL
// buffers on the render grid, taken on the GPU as the host path takes
// arrays (sim/optics/VolumeOptics.cpp, apps/library/FieldIntake.cpp).
//   The index: temperature and index (or δn) mapped to
//   δn = (n_base − n_ref) + [n_air(T) − n_air(T_ambient)] through the host
//   path's own text (common/gas_index.glsl), in float64, rounded once to
//   float32, into a buffer of the renderer's.
//   Extinction and scattering (added to a medium that has none): RGB alone,
//   read where they lie (the renderer's texture copies them), only checked
//   here; beside a density, or grey (one channel, spread to three), mapped
//   to κ = density_extinction·max(0, ρ) + the extinction and
//   σs = density_scattering·max(0, ρ) + the scattering through the host
//   path's own text (common/volume_coefficient.glsl), in float64, rounded
//   once to float32, into RGB buffers of the renderer's.
// Every check the host path makes records the first cell that fails it,
// which the renderer reads back (a few words) and refuses.
// The buffers the pass writes bind at the optical mapping's points
// (sim/optical_mapping.comp: here the solver's grid is the render grid;
// the density at its dye's), the caller's extinction and scattering at the
// solver's source and field, the checks at the solver's partials, read as
// uint as sim/find_nonfinite.comp reads them.
// Variants: EIKON_INDEX (δn written) with EIKON_TEMPERATURE (a temperature
// buffer) and EIKON_BASE (0: the medium's index, 1: an index n buffer, 2: a
// δn buffer); EIKON_EXTINCTION, EIKON_SCATTERING (their buffers' channels:
// 0 none, 1 grey, 3 RGB); EIKON_DENSITY (a density buffer); EIKON_WRITES_
// EXTINCTION, EIKON_WRITES_SCATTERING (κ, σs mapped and written).
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "common/gas_index.glsl"
#include "common/volume_coefficient.glsl"

layout(std430, binding = kOpticsTemperature) readonly buffer CallerTemperature { float temperature[]; };
layout(std430, binding = kOpticsConcentration) readonly buffer CallerBase { float base[]; };
layout(std430, binding = kOpticsDeltaIndex) writeonly buffer CallerDeltaIndex { float delta_index[]; };
layout(std430, binding = kSolverSource) readonly buffer CallerExtinction { float extinction[]; };
layout(std430, binding = kSolverField) readonly buffer CallerScattering { float scattering[]; };
layout(std430, binding = kOpticsDye) readonly buffer CallerDensity { float density[]; };
layout(std430, binding = kOpticsExtinction) writeonly buffer MappedExtinction { float mapped_extinction[]; };
layout(std430, binding = kOpticsScattering) writeonly buffer MappedScattering { float mapped_scattering[]; };
// Per check the first cell that fails it (0xffffffff: none), in the order
// of CallerCheck (apps/library/GpuFieldPass.cpp): [0] a temperature sample,
// [1] an index sample, [2] an extinction sample, [3] a scattering sample
// not finite; [4] T ≤ 0 K; [5] n ≤ 0 in the index; [6] n_ref + δn ≤ 0 or
// past float32; [7] κ < 0; [8] σs < 0; [9] σs > κ. Then [10] the smallest
// nonzero temperature sample's bits, where all are at least the bound
// below, and [11] 1 where a nonzero sample lies below it
// (absoluteLookingTemperature, sim/optics/VolumeOptics.h); [12] a density
// sample not finite; [13] the mapped κ, [14] the mapped σs past float32.
layout(std430, binding = kSolverPartials) buffer CallerChecks { uint checks[]; };

uniform ivec3 cells;
#if EIKON_DENSITY
uniform dvec3 density_extinction, density_scattering;  // 1/m per unit density (volume.density_*)
#endif
const double kFloatMax = 3.4028234663852886e38lf;      // the largest float32, exactly
#if EIKON_INDEX
uniform double ambient_temperature;  // K
uniform double refractivity, reference_temperature, reference_pressure;  // n0 − 1 at T0 (K), p0 (Pa)
uniform double pressure;              // Pa, volume.pressure
uniform double ambient_refractivity;  // n_air(T_ambient) − 1
uniform double reference_index;       // n_ref
#if EIKON_TEMPERATURE
uniform uint unit;                    // common/gas_index.glsl's numbering
uniform double temperature_scale, zero_celsius;
uniform float absolute_looking;       // K (kAbsoluteTemperatureLooking)
#endif
#if EIKON_BASE == 0
uniform double medium_delta;          // n_medium − n_ref
#endif
#endif

bool finiteBits(float value) { return (floatBitsToUint(value) & 0x7f800000u) != 0x7f800000u; }

void main() {
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(cell, cells))) return;
    uint c = uint(cell.x + cells.x * (cell.y + cells.y * cell.z));
#if EIKON_INDEX
    double t = ambient_temperature;
#if EIKON_TEMPERATURE
    float sample_value = temperature[c];
    if (!finiteBits(sample_value)) atomicMin(checks[0], c);
    if (sample_value != 0.0f && sample_value < absolute_looking) atomicOr(checks[11], 1u);
    if (sample_value > 0.0f) atomicMin(checks[10], floatBitsToUint(sample_value));
    t = sample_temperature(unit, double(sample_value), ambient_temperature, temperature_scale, zero_celsius);
#endif
    if (!(t > 0.0lf) || !finiteBits(float(t))) atomicMin(checks[4], c);
#if EIKON_BASE == 0
    double base_delta = medium_delta;
#elif EIKON_BASE == 1
    float n = base[c];
    if (!finiteBits(n)) atomicMin(checks[1], c);
    if (!(n > 0.0f)) atomicMin(checks[5], c);
    precise double base_delta = double(n) - reference_index;
#else
    float d = base[c];
    if (!finiteBits(d)) atomicMin(checks[1], c);
    double base_delta = double(d);
#endif
    double gas = gas_refractivity(refractivity, reference_temperature, reference_pressure, t, pressure);
    precise double delta = base_delta + gas - ambient_refractivity;
    if (!finiteBits(float(delta)) || !(reference_index + delta > 0.0lf)) atomicMin(checks[6], c);
    delta_index[c] = float(delta);
#endif
#if EIKON_DENSITY
    float rho = density[c];
    if (!finiteBits(rho)) atomicMin(checks[12], c);
#else
    float rho = 0.0f;
#endif
    for (uint channel = 0u; channel < 3u; ++channel) {
        uint k = 3u * c + channel;
        float kappa = 0.0f, sigma = 0.0f;  // the caller's, per channel
#if EIKON_EXTINCTION
        kappa = extinction[EIKON_EXTINCTION == 3 ? k : c];
        if (!finiteBits(kappa)) atomicMin(checks[2], c);
        if (kappa < 0.0f) atomicMin(checks[7], c);
#endif
#if EIKON_SCATTERING
        sigma = scattering[EIKON_SCATTERING == 3 ? k : c];
        if (!finiteBits(sigma)) atomicMin(checks[3], c);
        if (sigma < 0.0f) atomicMin(checks[8], c);
#endif
#if EIKON_WRITES_EXTINCTION
        // The host path's κ and σs (writeVolumeOptics), the medium's and a flame's terms none.
#if EIKON_DENSITY
        double kappa_rho = density_extinction[channel], sigma_rho = density_scattering[channel];
#else
        double kappa_rho = 0.0lf, sigma_rho = 0.0lf;
#endif
        double mapped_kappa = volume_coefficient(0.0lf, kappa_rho, double(rho), double(kappa), 0.0lf);
        double mapped_sigma = volume_coefficient(0.0lf, sigma_rho, double(rho), double(sigma), 0.0lf);
        if (!(abs(mapped_kappa) <= kFloatMax)) atomicMin(checks[13], c);
        if (!(abs(mapped_sigma) <= kFloatMax)) atomicMin(checks[14], c);
        if (mapped_sigma > mapped_kappa) atomicMin(checks[9], c);
        mapped_extinction[k] = float(mapped_kappa);
#if EIKON_WRITES_SCATTERING
        mapped_scattering[k] = float(mapped_sigma);
#endif
#elif EIKON_SCATTERING
        if (sigma > kappa) atomicMin(checks[9], c);  // a scattering buffer comes with an extinction buffer
#endif
    }
}
