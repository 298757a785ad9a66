// Index preparation on the GPU: Gaussian smoothing of δn (three separable
// passes of shaders/smooth_index.comp) and then (∇n, δn) by central
// differences (shaders/prepare_gradient.comp).
#pragma once

#include "bridge/scene/Scene.h"
#include "gl/GlObjects.h"
#include "render/stages/FieldTextures.h"

#include <vector>

namespace eikon::render {

class PrepareStage {
public:
    PrepareStage(const GridDesc& grid, const FieldTextures& fields);
    void run(FieldTextures& fields);
    // In place of run() where δn holds `deltaIndex` in every cell
    // (render/graph/UniformMedium.h): the gradient texture gets (0, 0, 0, δn),
    // what run() computes for such a field but for rounding in the smoothing.
    void fillUniform(FieldTextures& fields, float deltaIndex);

    // δn after smoothing (the raw field when smoothing is off).
    const gl::Texture3D& smoothedIndex(const FieldTextures& fields) const;

private:
    std::vector<float> kernel_;
    gl::Program smoothProgram_;
    gl::Program gradientProgram_;
    gl::Texture3D scratch_[2];
};

}  // namespace eikon::render
