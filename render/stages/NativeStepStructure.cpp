#include "render/stages/NativeStepStructure.h"

#include "render/stages/NativeCellLoop.h"

#include <algorithm>

namespace eikon::shader {
namespace {

// One level of common/octree_ranges.glsl over host arrays.
struct OctreeRangeKernel {
    render::OctreeRangeInputs inputs_;
    vec4* pyramid_;
    ivec3 pyramid_size_;
    ivec3 cells_;
    int level_;

    float range_index(ivec3 cell) const { return inputs_.smoothedIndex[render::cellOffset(cell, cells_)]; }
    // As octree_minmax.comp's: the largest κ channel, at least 1e-30 where the voxel glows.
    float range_extinction(ivec3 cell) const {
        const std::size_t at = render::cellOffset(cell, cells_);
        float kappa = 0.0f;
        if (inputs_.extinction) {
            const vec4 kappa3 = inputs_.extinction[at];
            kappa = max(kappa3.r, max(kappa3.g, kappa3.b));
        }
        if (inputs_.emission) {
            const vec4 glow = inputs_.emission[at];
            if (max(glow.r, max(glow.g, glow.b)) > 0.0f) kappa = max(kappa, 1e-30f);
        }
        return kappa;
    }
    vec4 finer_range(ivec3 texel) const { return pyramid_[render::cellOffset(texel, pyramid_size_)]; }
#include "shaders/common/octree_ranges.glsl"

    void operator()(ivec3 node) {
        pyramid_[render::cellOffset(octree_level_offset(cells_, level_) + node, pyramid_size_)] =
            node_range(node, cells_, level_);
    }
};

// common/octree_labels.glsl over host arrays.
struct OctreeLabelKernel {
    const vec4* pyramid_;
    ivec3 pyramid_size_;
    vec4* labels_;
    ivec3 cells_;
    OctreeLabelRule rule_;

    vec4 pyramid_range(ivec3 texel) const { return pyramid_[render::cellOffset(texel, pyramid_size_)]; }
#include "shaders/common/octree_labels.glsl"

    void operator()(ivec3 cell) { labels_[render::cellOffset(cell, cells_)] = vec4(octree_label(cell, cells_, rule_), 0.0f); }
};

}  // namespace
}  // namespace eikon::shader

namespace eikon::render {

void octreePyramidNative(const OctreeRangeInputs& inputs, const glm::ivec3& cells, std::vector<glm::vec4>& pyramid) {
    const glm::ivec3 size = shader::octree_pyramid_size(cells);
    pyramid.resize(static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y) * static_cast<std::size_t>(size.z));
    const int levels = shader::octree_levels(cells);
    for (int level = 0; level < levels; ++level)
        forEachCell(shader::octree_level_size(cells, level),
                    shader::OctreeRangeKernel{inputs, pyramid.data(), size, cells, level});
}

void octreeLabelsNative(const std::vector<glm::vec4>& pyramid, const glm::ivec3& cells, const shader::OctreeLabelRule& rule,
                        std::vector<glm::vec4>& labels) {
    labels.resize(static_cast<std::size_t>(cells.x) * static_cast<std::size_t>(cells.y) * static_cast<std::size_t>(cells.z));
    forEachCell(cells, shader::OctreeLabelKernel{pyramid.data(), shader::octree_pyramid_size(cells), labels.data(),
                                                 cells, rule});
}

}  // namespace eikon::render
