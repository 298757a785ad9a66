#include "render/stages/StepStructureStage.h"

#include "bridge/layout/GpuLayouts.h"
#include "gl/GlDebug.h"
#include "gl/ShaderLibrary.h"
#include "render/stages/NativeStepStructure.h"
#include "shaders/common/cpp_shim.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace eikon::render {

glm::ivec3 stepPyramidSize(const glm::ivec3& cells) { return shader::octree_pyramid_size(cells); }

StepStructureStage::StepStructureStage(const GridSpec& grid, const TracerDesc& tracer, bool hasExtinction,
                                       bool hasEmission, StageDevice device)
    : grid_(grid), tracer_(tracer), hasExtinction_(hasExtinction), hasEmission_(hasEmission), device_(device),
      levels_(shader::octree_levels(grid.resolution)) {
    const glm::ivec3 r = grid.resolution;
    if (device_ == StageDevice::Gpu) {
        minmaxProgram_ = gl::compileComputeProgram("octree_minmax.comp",
                                                   {{"EIKON_HAS_EXTINCTION", hasExtinction ? "1" : "0"},
                                                    {"EIKON_HAS_EMISSION", hasEmission ? "1" : "0"}});
        labelProgram_ = gl::compileComputeProgram("octree_label.comp");
        const glm::ivec3 size = stepPyramidSize(r);
        pyramid_ = gl::Texture3D(GL_RGBA32F, size.x, size.y, size.z,
                                 gl::gridResource("the octree step pyramid (" + std::to_string(levels_) + " levels in " +
                                                      std::to_string(size.x) + "×" + std::to_string(size.y) + "×" +
                                                      std::to_string(size.z) + " texels)",
                                                  r.x, r.y, r.z));
    }
    step_ = gl::Texture3D(GL_RGBA32F, r.x, r.y, r.z, gl::gridResource("the octree step sizes", r.x, r.y, r.z));
}

void StepStructureStage::enableReference(double minStep) {
    referenceMinStep_ = minStep;
    if (reference_.id()) return;
    const glm::ivec3 r = grid_.resolution;
    reference_ = gl::Texture3D(GL_RGBA32F, r.x, r.y, r.z, gl::gridResource("the reference step sizes", r.x, r.y, r.z));
}

void StepStructureStage::label(gl::Texture3D& target, double epsilon, double epsilonPrime, double minStep) {
    const glm::dvec3 h = grid_.voxelSize();
    const shader::OctreeLabelRule rule{
        static_cast<float>(epsilon),
        static_cast<float>(epsilonPrime),
        static_cast<float>(std::max({tracer_.dispersion.r, tracer_.dispersion.g, tracer_.dispersion.b})),
        static_cast<float>(tracer_.maxStepVoxels * grid_.smallestVoxelEdge()),
        static_cast<float>(minStep),
        static_cast<float>(std::max({h.x, h.y, h.z}) * std::sqrt(3.0)),
        static_cast<float>(kOpticalDepthTolerance)};
    if (device_ == StageDevice::Cpu) {
        octreeLabelsNative(hostPyramid_, grid_.resolution, rule, hostLabels_);
        target.upload(GL_RGBA, GL_FLOAT, hostLabels_.data());
        return;
    }
    labelProgram_.use();
    pyramid_.bindSampler(layout::kPyramidTexture);
    target.bindImage(layout::kStepImage, GL_WRITE_ONLY);
    glUniform1f(labelProgram_.uniform("rule.epsilon"), rule.epsilon);
    glUniform1f(labelProgram_.uniform("rule.epsilon_prime"), rule.epsilon_prime);
    glUniform1f(labelProgram_.uniform("rule.index_scale"), rule.index_scale);
    glUniform1f(labelProgram_.uniform("rule.capped_step"), rule.capped_step);
    glUniform1f(labelProgram_.uniform("rule.min_step"), rule.min_step);
    glUniform1f(labelProgram_.uniform("rule.node_edge"), rule.node_edge);
    glUniform1f(labelProgram_.uniform("rule.optical_depth_tolerance"), rule.optical_depth_tolerance);
    labelProgram_.dispatchOverCells(grid_.resolution);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
}

void StepStructureStage::run(const gl::Texture3D& smoothedIndex, const FieldTextures& fields) {
    if (device_ == StageDevice::Cpu)
        runNative(smoothedIndex, fields);
    else
        runCompute(smoothedIndex, fields);
    label(step_, tracer_.epsilon, tracer_.epsilonPrime, tracer_.stepVoxels * grid_.smallestVoxelEdge());
    if (reference_.id()) label(reference_, 0.0, 0.0, referenceMinStep_);
    gl::checkpoint("step structure stage");
}

void StepStructureStage::runNative(const gl::Texture3D& smoothedIndex, const FieldTextures& fields) {
    const auto cells = static_cast<std::size_t>(grid_.cellCount());
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);  // after the compute shaders' writes to the inputs
    hostIndex_.resize(cells);
    downloadTexels(smoothedIndex, GL_RED, hostIndex_.data(), cells * sizeof(float));
    OctreeRangeInputs inputs{hostIndex_.data()};
    if (hasExtinction_) {
        hostExtinction_.resize(cells);
        // As the texels are stored (RGBA32F): a copy, where RGB would be converted texel by texel.
        downloadTexels(fields.extinction(), GL_RGBA, hostExtinction_.data(), cells * sizeof(glm::vec4));
        inputs.extinction = hostExtinction_.data();
    }
    if (hasEmission_) {
        hostEmission_.resize(cells);
        downloadTexels(fields.emission(), GL_RGBA, hostEmission_.data(), cells * sizeof(glm::vec4));
        inputs.emission = hostEmission_.data();
    }
    octreePyramidNative(inputs, grid_.resolution, hostPyramid_);
}

void StepStructureStage::runCompute(const gl::Texture3D& smoothedIndex, const FieldTextures& fields) {
    minmaxProgram_.use();
    smoothedIndex.bindSampler(layout::kIndexTexture);
    // One texture holds every level: read level k − 1 and write level k of it.
    pyramid_.bindImage(layout::kFinerLevelImage, GL_READ_ONLY);
    pyramid_.bindImage(layout::kPyramidLevelImage, GL_WRITE_ONLY);
    if (fields.hasExtinction() || fields.hasEmission()) fields.bindForTracing();  // κ, ε at their texture units
    for (int level = 0; level < levels_; ++level) {
        glUniform1i(minmaxProgram_.uniform("level"), level);
        minmaxProgram_.dispatchOverCells(shader::octree_level_size(grid_.resolution, level));
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    }
}

void StepStructureStage::fillUniform(bool emptyOfExtinction) {
    const float texel[4] = {static_cast<float>(levels_ - 1), 1e30f, emptyOfExtinction ? 1.0f : 0.0f, 0.0f};
    glClearTexImage(step_.id(), 0, GL_RGBA, GL_FLOAT, texel);
    if (reference_.id()) glClearTexImage(reference_.id(), 0, GL_RGBA, GL_FLOAT, texel);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    gl::checkpoint("step structure stage, uniform medium");
}

}  // namespace eikon::render
