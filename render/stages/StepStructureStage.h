// The step-size structure of [Sun08] (§4.2, §5.3) on the GPU: a
// min/max pyramid of δn (shaders/octree_minmax.comp), then per voxel the
// level of the largest octree node around it whose index varies by less than
// ε (no step cap) or ε′ (step capped), and whose extinction varies by less
// than kOpticalDepthTolerance across it, in shaders/octree_label.comp.
// Rebuilt whenever the index or extinction changes (emission shares κ's
// version; an emitting voxel is never an empty node).
#pragma once

#include "bridge/grid/GridSpec.h"
#include "bridge/scene/Scene.h"
#include "gl/GlObjects.h"
#include "render/stages/FieldTextures.h"

namespace eikon::render {

// Largest change of optical depth κ·ℓ across a node's diagonal that still
// lets a photon cross it in one step (1% in transmittance).
constexpr double kOpticalDepthTolerance = 0.01;

class StepStructureStage {
public:
    StepStructureStage(const GridSpec& grid, const TracerDesc& tracer, bool hasExtinction, bool hasEmission);

    void run(const gl::Texture3D& smoothedIndex, const FieldTextures& fields);
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
    glm::ivec3 paddedSize_{1};
    gl::Program minmaxProgram_;
    gl::Program labelProgram_;
    gl::Texture3D pyramid_;
    gl::Texture3D step_;
    gl::Texture3D reference_;  // with enableReference
    double referenceMinStep_ = 0.0;
};

}  // namespace eikon::render
