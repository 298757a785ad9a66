// The energy balance and error figures of a light pass (photons or
// wavefronts). C++ mirror: layout::GpuPhotonStats (powers in 64-bit fixed
// point), indexed by the tallies kEmitted … of layout::PowerTally. GLSL only.
layout(std430, binding = kPhotonStats) buffer PhotonStats {
    uint power_tallies[2 * 3 * kTallyCount];  // [2·(3·tally + channel) + word]
    uint photon_tallies[4];   // escaped, received, cut off, blocked
    uint step_tallies[4];     // low word, high word, max invariant error bits
    uint deposit_tallies[4];  // low word, high word
    uint invariant_tallies[4];  // low word, high word: Σ over steps of the relative invariant error, fixed point
    uint surface_tallies[4];  // events at sharp surfaces: reflected, transmitted
};

#include "common/invariant_units.glsl"
