#include "render/stages/StepStructureStage.h"

#include "bridge/layout/GpuLayouts.h"
#include "gl/GlDebug.h"
#include "gl/ShaderLibrary.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace eikon::render {

StepStructureStage::StepStructureStage(const GridSpec& grid, const TracerDesc& tracer, bool hasExtinction,
                                       bool hasEmission)
    : grid_(grid), tracer_(tracer),
      minmaxProgram_(gl::compileComputeProgram("octree_minmax.comp",
                                               {{"EIKON_HAS_EXTINCTION", hasExtinction ? "1" : "0"},
                                                {"EIKON_HAS_EMISSION", hasEmission ? "1" : "0"}})),
      labelProgram_(gl::compileComputeProgram("octree_label.comp")) {
    // Levels until one node spans the grid; level 0 padded to a multiple of
    // the coarsest node so that every level halves exactly (a mip chain).
    const int largest = std::max({grid.resolution.x, grid.resolution.y, grid.resolution.z});
    while ((1 << (levels_ - 1)) < largest) ++levels_;
    const int coarsest = 1 << (levels_ - 1);
    paddedSize_ = (grid.resolution + coarsest - 1) / coarsest * coarsest;
    const glm::ivec3 r = grid.resolution;
    pyramid_ = gl::Texture3D(GL_RGBA32F, paddedSize_.x, paddedSize_.y, paddedSize_.z, levels_,
                             gl::gridResource("the octree step pyramid (padded to " + std::to_string(paddedSize_.x) +
                                                  "³, " + std::to_string(levels_) + " levels)",
                                              r.x, r.y, r.z));
    step_ = gl::Texture3D(GL_RGBA32F, r.x, r.y, r.z, gl::gridResource("the octree step sizes", r.x, r.y, r.z));
}

void StepStructureStage::enableReference(double minStep) {
    referenceMinStep_ = minStep;
    if (reference_.id()) return;
    const glm::ivec3 r = grid_.resolution;
    reference_ = gl::Texture3D(GL_RGBA32F, r.x, r.y, r.z, gl::gridResource("the reference step sizes", r.x, r.y, r.z));
}

void StepStructureStage::label(const gl::Texture3D& target, double epsilon, double epsilonPrime, double minStep) {
    const float maxDispersion = static_cast<float>(std::max({tracer_.dispersion.r, tracer_.dispersion.g, tracer_.dispersion.b}));
    labelProgram_.use();
    pyramid_.bindSampler(layout::kPyramidTexture);
    target.bindImage(layout::kStepImage, GL_WRITE_ONLY);
    glUniform1i(labelProgram_.uniform("levels"), levels_);
    glUniform1f(labelProgram_.uniform("epsilon"), static_cast<float>(epsilon));
    glUniform1f(labelProgram_.uniform("epsilon_prime"), static_cast<float>(epsilonPrime));
    glUniform1f(labelProgram_.uniform("index_scale"), maxDispersion);
    glUniform1f(labelProgram_.uniform("capped_step"),
                static_cast<float>(tracer_.maxStepVoxels * grid_.smallestVoxelEdge()));
    glUniform1f(labelProgram_.uniform("min_step"), static_cast<float>(minStep));
    const glm::dvec3 h = grid_.voxelSize();
    glUniform1f(labelProgram_.uniform("node_edge"), static_cast<float>(std::max({h.x, h.y, h.z}) * std::sqrt(3.0)));
    glUniform1f(labelProgram_.uniform("optical_depth_tolerance"), static_cast<float>(kOpticalDepthTolerance));
    labelProgram_.dispatchOverCells(grid_.resolution);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
}

void StepStructureStage::run(const gl::Texture3D& smoothedIndex, const FieldTextures& fields) {
    minmaxProgram_.use();
    smoothedIndex.bindSampler(layout::kIndexTexture);
    if (fields.hasExtinction() || fields.hasEmission()) fields.bindForTracing();  // κ, ε at their texture units
    for (int level = 0; level < levels_; ++level) {
        glUniform1i(minmaxProgram_.uniform("level"), level);
        if (level > 0)
            glBindImageTexture(layout::kFinerLevelImage, pyramid_.id(), level - 1, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
        glBindImageTexture(layout::kPyramidLevelImage, pyramid_.id(), level, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
        minmaxProgram_.dispatchOverCells(glm::max(paddedSize_ >> level, glm::ivec3(1)));
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    }
    label(step_, tracer_.epsilon, tracer_.epsilonPrime, tracer_.stepVoxels * grid_.smallestVoxelEdge());
    if (reference_.id()) label(reference_, 0.0, 0.0, referenceMinStep_);
    gl::checkpoint("step structure stage");
}

}  // namespace eikon::render
