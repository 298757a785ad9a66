// How far one output is from another, as the error estimates measure it
// (render/stages/ErrorEstimateStage.h, render/stages/DiagnosticErrorEstimate.h).
#pragma once

#include <cstddef>
#include <vector>

namespace eikon::render {

// ‖a − b‖₁ / ‖b‖₁ over the RGB of every pixel (RGBA); 0 where b is 0.
double relativeL1OfRgb(const std::vector<float>& a, const std::vector<float>& b);

// Σ|a − b| / Σ|b| over elements of `components` floats each (a vector per
// pixel, |·| its Euclidean length); 0 where b is 0.
double relativeL1OfVectors(const std::vector<float>& a, const std::vector<float>& b, std::size_t components);

}  // namespace eikon::render
