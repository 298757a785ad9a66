#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

namespace eikon::test {

gl::GlContext& glContext() {
    static std::unique_ptr<gl::GlContext> context = gl::createHeadlessContext();
    context->makeCurrent();
    return *context;
}

void reportFigure(const char* name, double value) {
    std::printf("[ figure   ] %s = %.6g\n", name, value);
    ::testing::Test::RecordProperty(name, std::to_string(value));
}

}  // namespace eikon::test
