// The prepare stage's kernels on the CPU: the very text the compute shaders
// run (common/index_smoothing.glsl, common/index_gradient.glsl), compiled as
// C++ through cpp_shim.h and called from TBB loops over host arrays.
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace eikon::render {

// `index` (one float a cell, x fastest) smoothed along x, then y, then z
// with the half kernel `weights` (GaussianKernel.h); `scratch` is resized to
// the grid and used between the passes.
void smoothIndexNative(std::vector<float>& index, const glm::ivec3& cells, const std::vector<float>& weights,
                       std::vector<float>& scratch);

// (∇n, δn) per cell into `gradient` from smoothed δn; `voxelSize` as the
// grid block gives it to the shader (float metres).
void indexGradientNative(const std::vector<float>& smoothed, const glm::ivec3& cells, const glm::vec3& voxelSize,
                         std::vector<glm::vec4>& gradient);

}  // namespace eikon::render
