// Index preparation on the GPU: (∇n, δn) from δn (shaders/prepare_gradient.comp).
#pragma once

#include "render/gl/GlObjects.h"
#include "render/stages/FieldTextures.h"

namespace eikon::render {

class PrepareStage {
public:
    PrepareStage();
    void run(FieldTextures& fields);

private:
    gl::Program program_;
};

}  // namespace eikon::render
