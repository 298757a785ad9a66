// A stride for sampling every k-th photon of a pass so that the sample
// spreads over all of each emitter's strata.
#pragma once

namespace eikon {

// The largest prime <= n (n >= 2), or 1: photon i of an emitter takes
// stratum (i mod s, i / s) of an s × s grid, and a prime stride longer than
// s shares no factor with it, so the sampled photons spread over all strata.
long long largestPrimeAtMost(long long n);

}  // namespace eikon
