// The windowed OpenGL context (GLFW), run under Xvfb by ctest: it must give
// OpenGL 4.5 core and run eikon's compute shaders like the headless one.
#include "bridge/layout/GpuLayouts.h"
#include "render/gl/GlContext.h"
#include "render/gl/GlObjects.h"
#include "render/gl/ShaderLibrary.h"

#include <gtest/gtest.h>

#include <glm/vec4.hpp>

#include <vector>

namespace eikon {
namespace {

TEST(WindowContext, OpensWithOpenGl45AndRunsComputeShaders) {
    const auto window = gl::createWindowContext(64, 48, "eikon test");
    EXPECT_EQ(window->info().version.rfind("4.5", 0), 0u) << window->info().version;
    int width = 0, height = 0;
    window->framebufferSize(width, height);
    EXPECT_EQ(width, 64);
    EXPECT_EQ(height, 48);

    // The shared-math probe on one case: the Euler step moves x by (ds/n)·v.
    std::vector<glm::vec4> probe(8, glm::vec4(0.0f));
    probe[0] = glm::vec4(0.25f, 0.5f, 0.0f, 2.0f);  // x, n
    probe[1] = glm::vec4(2.0f, 0.0f, 0.0f, 0.1f);   // v, ds
    gl::Buffer buffer(probe.size() * sizeof(glm::vec4), probe.data());
    const gl::Program program = gl::compileComputeProgram("shared_math_probe.comp");
    buffer.bindStorage(layout::kProbe);
    program.use();
    glUniform1ui(program.uniform("case_count"), 1);
    program.dispatchCovering(1, 1, 1, 64, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    buffer.download(probe.data(), probe.size() * sizeof(glm::vec4));
    EXPECT_FLOAT_EQ(probe[4].x, 0.25f + 0.1f / 2.0f * 2.0f);
    window->swapBuffers();
}

}  // namespace
}  // namespace eikon
