// The step structure's kernels on the CPU: the very text the compute shaders
// run (common/octree_ranges.glsl, common/octree_labels.glsl over
// common/octree_levels.glsl's placement), compiled as C++ through
// cpp_shim.h and called from TBB loops over host arrays.
#pragma once

#include "shaders/common/cpp_shim.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace eikon::render {

// Level-0 inputs, one entry a cell (x fastest); null where the field is absent.
struct OctreeRangeInputs {
    const float* smoothedIndex = nullptr;
    const glm::vec4* extinction = nullptr;  // κ per channel (rgb; the textures' RGBA texels)
    const glm::vec4* emission = nullptr;    // ε per channel (rgb)
};

// Every level of the min/max pyramid into `pyramid`, a texture of
// shader::octree_pyramid_size(cells) texels (x fastest).
void octreePyramidNative(const OctreeRangeInputs& inputs, const glm::ivec3& cells, std::vector<glm::vec4>& pyramid);

// Each voxel's (level, step cap, empty, 0) from the pyramid.
void octreeLabelsNative(const std::vector<glm::vec4>& pyramid, const glm::ivec3& cells, const shader::OctreeLabelRule& rule,
                        std::vector<glm::vec4>& labels);

}  // namespace eikon::render
