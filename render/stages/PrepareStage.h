// Index preparation: Gaussian smoothing of δn (three separable passes of
// common/index_smoothing.glsl) and then (∇n, δn) by central differences
// (common/index_gradient.glsl), as compute shaders (smooth_index.comp,
// prepare_gradient.comp) or as native loops over the same kernels
// (NativePrepare.h), which read δn from its texture and write the smoothed
// δn and the gradient to the textures the compute shaders write.
#pragma once

#include "bridge/scene/Scene.h"
#include "gl/GlObjects.h"
#include "render/stages/FieldTextures.h"
#include "render/stages/StageDevice.h"

#include <vector>

namespace eikon::render {

class PrepareStage {
public:
    PrepareStage(const GridDesc& grid, const FieldTextures& fields, StageDevice device = StageDevice::Gpu);
    StageDevice device() const { return device_; }
    void run(FieldTextures& fields);
    // In place of run() where δn holds `deltaIndex` in every cell
    // (render/graph/UniformMedium.h): the gradient texture gets (0, 0, 0, δn),
    // what run() computes for such a field but for rounding in the smoothing.
    void fillUniform(FieldTextures& fields, float deltaIndex);

    // δn after smoothing (the raw field when smoothing is off).
    const gl::Texture3D& smoothedIndex(const FieldTextures& fields) const;

private:
    void runCompute(FieldTextures& fields);
    void runNative(FieldTextures& fields);

    StageDevice device_;
    std::vector<float> kernel_;
    gl::Program smoothProgram_;    // compute shaders only
    gl::Program gradientProgram_;  // compute shaders only
    gl::Texture3D scratch_[2];
    std::vector<float> hostIndex_, hostScratch_;  // native only
    std::vector<glm::vec4> hostGradient_;         // native only
};

}  // namespace eikon::render
