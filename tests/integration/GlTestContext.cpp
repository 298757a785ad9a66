#include "tests/integration/GlTestContext.h"

#include <memory>

namespace eikon::test {

gl::GlContext& glContext() {
    static std::unique_ptr<gl::GlContext> context = gl::createHeadlessContext();
    context->makeCurrent();
    return *context;
}

}  // namespace eikon::test
