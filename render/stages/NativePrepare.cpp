#include "render/stages/NativePrepare.h"

#include "render/stages/NativeCellLoop.h"
#include "shaders/common/cpp_shim.h"

#include <utility>

namespace eikon::shader {
namespace {

// One axis of common/index_smoothing.glsl over host arrays.
struct IndexSmoothingKernel {
    const float* source_;
    float* target_;
    ivec3 cells_;
    ivec3 axis_;
    const float* weights_;
    int radius_;

    float smoothing_source(ivec3 cell) const { return source_[render::cellOffset(cell, cells_)]; }
    float smoothing_weight(int offset) const { return weights_[offset]; }
#include "shaders/common/index_smoothing.glsl"

    void operator()(ivec3 cell) {
        target_[render::cellOffset(cell, cells_)] = smoothed_along_axis(cell, cells_, axis_, radius_);
    }
};

// common/index_gradient.glsl over host arrays.
struct IndexGradientKernel {
    const float* smoothed_;
    vec4* gradient_;
    ivec3 cells_;
    vec3 voxel_size_;

    float gradient_source(ivec3 cell) const { return smoothed_[render::cellOffset(cell, cells_)]; }
#include "shaders/common/index_gradient.glsl"

    void operator()(ivec3 cell) { gradient_[render::cellOffset(cell, cells_)] = gradient_and_index(cell, cells_, voxel_size_); }
};

}  // namespace
}  // namespace eikon::shader

namespace eikon::render {

void smoothIndexNative(std::vector<float>& index, const glm::ivec3& cells, const std::vector<float>& weights,
                       std::vector<float>& scratch) {
    scratch.resize(index.size());
    const int radius = static_cast<int>(weights.size()) - 1;
    for (const glm::ivec3 axis : {glm::ivec3(1, 0, 0), glm::ivec3(0, 1, 0), glm::ivec3(0, 0, 1)}) {
        forEachCell(cells, shader::IndexSmoothingKernel{index.data(), scratch.data(), cells, axis, weights.data(), radius});
        std::swap(index, scratch);
    }
}

void indexGradientNative(const std::vector<float>& smoothed, const glm::ivec3& cells, const glm::vec3& voxelSize,
                         std::vector<glm::vec4>& gradient) {
    gradient.resize(smoothed.size());
    forEachCell(cells, shader::IndexGradientKernel{smoothed.data(), gradient.data(), cells, voxelSize});
}

}  // namespace eikon::render
