// The step-size structure of [Sun08] (§4.2, §5.3) on the GPU: a
// min/max pyramid of δn (shaders/octree_minmax.comp), then per voxel the
// level of the largest octree node around it whose index varies by less than
// ε (no step cap) or ε′ (step capped), and whose extinction varies by less
// than kOpticalDepthTolerance across it, in shaders/octree_label.comp.
// Rebuilt whenever the index or extinction changes (emission shares κ's
// version; an emitting voxel is never an empty node).
//
// The pyramid covers the grid's own cells, not a cube of 2^k around them
// (common/octree_levels.glsl): a node of level k still spans the voxels
// [n·2^k, (n + 1)·2^k), so the readers' node geometry (common/step_size.glsl)
// is that of the padded octree, while the cells a padding added — copies of
// the edge that change no node's range — are neither stored nor reduced.
#pragma once

#include "bridge/grid/GridSpec.h"
#include "bridge/scene/Scene.h"
#include "gl/GlObjects.h"
#include "render/stages/FieldTextures.h"

namespace eikon::render {

// Largest change of optical depth κ·ℓ across a node's diagonal that still
// lets a photon cross it in one step (1% in transmittance).
constexpr double kOpticalDepthTolerance = 0.01;

// Texels of the pyramid texture over `cells` (common/octree_levels.glsl).
glm::ivec3 stepPyramidSize(const glm::ivec3& cells);

class StepStructureStage {
public:
    StepStructureStage(const GridSpec& grid, const TracerDesc& tracer, bool hasExtinction, bool hasEmission);

    void run(const gl::Texture3D& smoothedIndex, const FieldTextures& fields);
    // In place of run() where δn and κ each hold one value in every cell and
    // nothing glows (render/graph/UniformMedium.h): every voxel, and every
    // reference voxel, is in the one node of the top level, uncapped; the
    // label octree_label.comp gives such a field, written without the pyramid.
    void fillUniform(bool emptyOfExtinction);
    // rgba32f per voxel: (octree level, step cap in metres or 1e30 for none,
    // 1 where the node holds no extinction, 0).
    const gl::Texture3D& stepTexture() const { return step_; }
    int levels() const { return levels_; }
    // Also labels, on every run, a reference structure for the
    // discretisation estimate: long steps only through nodes whose index and
    // extinction are exactly uniform (ε = ε′ = 0, where a straight flight is
    // exact), `minStep` (metres) everywhere else.
    void enableReference(double minStep);
    const gl::Texture3D& referenceStepTexture() const { return reference_; }

private:
    void label(const gl::Texture3D& target, double epsilon, double epsilonPrime, double minStep);

    GridSpec grid_;
    TracerDesc tracer_;
    int levels_ = 1;
    gl::Program minmaxProgram_;
    gl::Program labelProgram_;
    gl::Texture3D pyramid_;  // every level, placed by common/octree_levels.glsl
    gl::Texture3D step_;
    gl::Texture3D reference_;  // with enableReference
    double referenceMinStep_ = 0.0;
};

}  // namespace eikon::render
