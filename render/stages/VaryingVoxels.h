// Where a frame's optical fields vary: the box of voxels whose δn or κ
// differ from the grid's first voxel's. Outside it, grown by the reach of
// the smoothing, the central differences and the trilinear filter, the
// traced medium is that voxel's, uniform, and a diagnostic's ray crosses it
// straight (DiagnosticStage::setVaryingVoxels).
#pragma once

#include "render/stages/FieldTextures.h"

#include <glm/vec3.hpp>
#include <glm/vector_relational.hpp>

namespace eikon::render {

struct VoxelBox {
    glm::ivec3 lowest{0}, highest{-1};  // inclusive corners; empty where any lowest > highest
    bool empty() const { return glm::any(glm::greaterThan(lowest, highest)); }
};

struct VaryingVoxels {
    VoxelBox box;
    float uniformDelta = 0.0f;    // δn outside the box: the first voxel's
    glm::vec3 uniformExtinction{0.0f};  // κ rgb outside it, 1/m
};

// The voxels of `fields` whose δn or κ differ from voxel (0, 0, 0)'s; the
// whole grid where either is on the GPU only (a solver's ring), which is
// not read back to find out.
VaryingVoxels varyingVoxels(const FieldUpload& fields);

}  // namespace eikon::render
