// Separable Gaussian smoothing of a scalar grid (x fastest), TBB-parallel.
// The kernel has radius floor(3σ) voxels — σ = 1.5 gives Sun et al.'s 9³
// window with σ = window/6 — and is renormalised to sum to 1; samples beyond
// the grid take the value of the nearest edge cell.
#pragma once

#include <glm/vec3.hpp>

#include <vector>

namespace eikon::sim {

std::vector<double> gaussianKernel(double sigmaVoxels);

// σ ≤ 0 leaves the values unchanged.
void gaussianSmooth(std::vector<float>& values, const glm::ivec3& resolution, double sigmaVoxels);

}  // namespace eikon::sim
