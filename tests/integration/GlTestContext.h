// One headless OpenGL 4.5 context per test binary (Mesa llvmpipe on machines
// without a GPU), made current on first use.
#pragma once

#include "render/gl/GlContext.h"

namespace eikon::test {

gl::GlContext& glContext();

}  // namespace eikon::test
