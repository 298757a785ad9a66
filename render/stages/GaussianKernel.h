// The Gaussian kernel that smooths the index field ([Sun08] §4.1).
#pragma once

#include <vector>

namespace eikon::render {

constexpr int kMaxSmoothingRadius = 31;  // shaders/smooth_index.comp's MAX_RADIUS

// Half of a normalised, symmetric Gaussian kernel: weights[|offset|] for
// offsets 0..radius, where the full kernel sums to one. The window is
// `windowVoxels` wide (odd) or, when 0, 2·floor(3σ) + 1 — 9 for σ = 1.5,
// [Sun08]'s 9³ window with σ = window/6 — at most kMaxSmoothingRadius voxels
// either side. σ ≤ 0 gives the identity {1}.
std::vector<float> gaussianHalfKernel(double sigmaVoxels, int windowVoxels = 0);

}  // namespace eikon::render
