// The receiver filter's 3×3 binomial kernel (shaders/receiver_filter.comp:
// [1 2 1]/4 along each axis, weights outside the map left out and the rest
// renormalised) on the CPU, so that a ground-truth map can be compared with
// a receiver map as the same estimator.
#pragma once

#include <vector>

namespace eikon::reference {

// `map` holds resolution² values, row j at j·resolution.
std::vector<double> binomialFilter(const std::vector<double>& map, int resolution);

}  // namespace eikon::reference
