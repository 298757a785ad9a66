// The energy balance and error figures of a light pass (photons or
// wavefronts). Members: layout::GpuPhotonStats (powers in 64-bit fixed
// point), indexed by the tallies kEmitted … of layout::PowerTally. GLSL only.
layout(std430, binding = kPhotonStats) buffer PhotonStats { EIKON_GPU_PHOTON_STATS };

// A ray's summed invariant error as a 64-bit fixed-point number of 2^-32
// units (high word: the whole part): integer sums do not depend on the order
// rays finish in, so a pass gives the same bits however it is dispatched or
// shared among processes.
uvec2 invariant_units(float error_sum) {
    if (!(error_sum < 4.0e9f)) error_sum = 4.0e9f;  // a diverged ray (or NaN) saturates, past any meaningful mean
    float whole = floor(error_sum);
    return uvec2(uint((error_sum - whole) * 4294967296.0f), uint(whole));
}
