// One headless OpenGL 4.5 context per test binary (Mesa llvmpipe on machines
// without a GPU), made current on first use.
#pragma once

#include "gl/GlContext.h"

namespace eikon::test {

gl::GlContext& glContext();

// Prints a measured figure and records it in the test's XML properties, so
// accuracy figures can be read off a test run.
void reportFigure(const char* name, double value);

}  // namespace eikon::test
