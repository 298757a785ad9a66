// The energy balance and error figures of a light pass (photons or
// wavefronts). Members: layout::GpuPhotonStats (powers in 64-bit fixed
// point), indexed by the tallies kEmitted … of layout::PowerTally. GLSL only.
layout(std430, binding = kPhotonStats) buffer PhotonStats { EIKON_GPU_PHOTON_STATS };

#include "common/invariant_units.glsl"
