// Where a frame's optical fields vary: the box of voxels whose δn or κ
// differ from the grid's first voxel's. Outside it, grown by the reach of
// the smoothing, the central differences and the trilinear filter, the
// traced medium is that voxel's, uniform, and a diagnostic's ray crosses it
// straight (DiagnosticStage::setVaryingVoxels). Inside it, the lowest and
// highest δn and κ of each brick of voxels, from which the diagnostic finds
// where the medium is nearly uniform (DiagnosticNodeSteps.h).
#pragma once

#include "render/stages/FieldTextures.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <glm/vector_relational.hpp>

#include <vector>

namespace eikon::render {

struct VoxelBox {
    glm::ivec3 lowest{0}, highest{-1};  // inclusive corners; empty where any lowest > highest
    bool empty() const { return glm::any(glm::greaterThan(lowest, highest)); }
};

// Per brick of kVoxels³ voxels (the last ones on an axis cut by the grid's
// face), x fastest: the lowest and highest (δn, κ r, κ g, κ b) among its voxels.
struct BrickRanges {
    static constexpr int kVoxels = 4;
    glm::ivec3 count{0};  // bricks per axis; none where the fields are not on the host
    std::vector<glm::vec4> lowest, highest;
    bool empty() const { return lowest.empty(); }
    std::size_t index(const glm::ivec3& brick) const {
        return static_cast<std::size_t>(brick.x) +
               static_cast<std::size_t>(count.x) * (static_cast<std::size_t>(brick.y) +
                                                    static_cast<std::size_t>(count.y) * static_cast<std::size_t>(brick.z));
    }
};

struct VaryingVoxels {
    VoxelBox box;
    BrickRanges bricks;
    float uniformDelta = 0.0f;    // δn outside the box: the first voxel's
    glm::vec3 uniformExtinction{0.0f};  // κ rgb outside it, 1/m
    bool greyExtinction = false;  // κ r = g = b in every voxel (false where not known)
};

// The voxels of `fields` whose δn or κ differ from voxel (0, 0, 0)'s; the
// whole grid, and no bricks, where either is on the GPU only (a solver's
// ring), which is not read back to find out.
VaryingVoxels varyingVoxels(const FieldUpload& fields);

}  // namespace eikon::render
