// The step-size structure of [Sun08] (§4.2, §5.3): a min/max pyramid of δn
// (common/octree_ranges.glsl), then per voxel the level of the largest
// octree node around it whose index varies by less than ε (no step cap) or
// ε′ (step capped), and whose extinction varies by less than
// kOpticalDepthTolerance across it (common/octree_labels.glsl); as compute
// shaders (octree_minmax.comp, octree_label.comp) or as native loops over
// the same kernels (NativeStepStructure.h), which read the smoothed δn, κ and
// ε from their textures, keep the pyramid in host memory and write the
// labels to the textures the compute shaders write.
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
#include "render/stages/StageDevice.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace eikon::render {

// Largest change of optical depth κ·ℓ across a node's diagonal that still
// lets a photon cross it in one step (1% in transmittance).
constexpr double kOpticalDepthTolerance = 0.01;

// Texels of the pyramid texture over `cells` (common/octree_levels.glsl).
glm::ivec3 stepPyramidSize(const glm::ivec3& cells);

class StepStructureStage {
public:
    StepStructureStage(const GridSpec& grid, const TracerDesc& tracer, bool hasExtinction, bool hasEmission,
                       StageDevice device = StageDevice::Gpu);
    StageDevice device() const { return device_; }

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
    void runCompute(const gl::Texture3D& smoothedIndex, const FieldTextures& fields);
    void runNative(const gl::Texture3D& smoothedIndex, const FieldTextures& fields);
    // Labels `target` from the pyramid (on the stage's device).
    void label(gl::Texture3D& target, double epsilon, double epsilonPrime, double minStep);

    GridSpec grid_;
    TracerDesc tracer_;
    bool hasExtinction_, hasEmission_;
    StageDevice device_;
    int levels_ = 1;
    gl::Program minmaxProgram_;  // compute shaders only
    gl::Program labelProgram_;   // compute shaders only
    gl::Texture3D pyramid_;  // every level, placed by common/octree_levels.glsl; compute shaders only
    std::vector<float> hostIndex_;                                               // native only
    std::vector<glm::vec4> hostExtinction_, hostEmission_, hostPyramid_, hostLabels_;  // native only
    gl::Texture3D step_;
    gl::Texture3D reference_;  // with enableReference
    double referenceMinStep_ = 0.0;
};

}  // namespace eikon::render
