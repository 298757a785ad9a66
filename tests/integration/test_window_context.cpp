// The windowed OpenGL context (GLFW), run under Xvfb by ctest: it must give
// OpenGL 4.5 core and run eikon's compute shaders like the headless one.
#include "gl/GlContext.h"
#include "gl/GlObjects.h"
#include "gl/ShaderLibrary.h"

#include <gtest/gtest.h>

#include <glm/vec4.hpp>

#include <vector>

namespace eikon {
namespace {

// One Euler step of the shared ray math (shaders/common/ray_step.glsl).
constexpr const char* kEulerProbe = R"(layout(local_size_x = 1) in;
#include "common/ray_step.glsl"
layout(std430, binding = 0) buffer Probe { vec4 probe[]; };
void main() {
    vec3 x = probe[0].xyz;
    vec3 v = probe[1].xyz;
    vec3 x_lost = vec3(0.0f);
    eikonal_euler_step(x, x_lost, v, probe[0].w, vec3(0.0f), probe[1].w);
    probe[2] = vec4(x, 0.0f);
}
)";

TEST(WindowContext, OpensWithOpenGl45AndRunsComputeShaders) {
    const auto window = gl::createWindowContext(64, 48, "eikon test");
    EXPECT_EQ(window->info().version.rfind("4.5", 0), 0u) << window->info().version;
    int width = 0, height = 0;
    window->framebufferSize(width, height);
    EXPECT_EQ(width, 64);
    EXPECT_EQ(height, 48);

    // The Euler step moves x by (ds/n)·v.
    std::vector<glm::vec4> probe(3, glm::vec4(0.0f));
    probe[0] = glm::vec4(0.25f, 0.5f, 0.0f, 2.0f);  // x, n
    probe[1] = glm::vec4(2.0f, 0.0f, 0.0f, 0.1f);   // v, ds
    gl::Buffer buffer(probe.size() * sizeof(glm::vec4), probe.data());
    const gl::Program program = gl::compileComputeProgramFromSource("euler_probe.comp", kEulerProbe);
    buffer.bindStorage(0);
    program.dispatchCovering(1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    buffer.download(probe.data(), probe.size() * sizeof(glm::vec4));
    EXPECT_FLOAT_EQ(probe[2].x, 0.25f + 0.1f / 2.0f * 2.0f);
    window->swapBuffers();
}

}  // namespace
}  // namespace eikon
