// A window with an OpenGL 4.5 core context through GLFW.
#include "gl/GlContext.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <stdexcept>
#include <string>

namespace eikon::gl {

namespace {

class GlfwContext final : public WindowContext {
public:
    GlfwContext(int width, int height, const std::string& title) {
        glfwSetErrorCallback(nullptr);
        if (!glfwInit()) throw std::runtime_error("GLFW could not initialise (no display? set DISPLAY or use Xvfb)");
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
#ifndef NDEBUG
        glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
#endif
        window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
        if (!window_) {
            const char* reason = nullptr;
            glfwGetError(&reason);
            glfwTerminate();
            throw std::runtime_error(std::string("GLFW window with an OpenGL 4.5 core context: ") +
                                     (reason ? reason : "failed"));
        }
        makeCurrent();
        initialiseCurrent("GLFW window");
    }
    ~GlfwContext() override {
        glfwDestroyWindow(window_);
        glfwTerminate();
    }
    void makeCurrent() override { glfwMakeContextCurrent(window_); }
    bool shouldClose() const override { return glfwWindowShouldClose(window_); }
    void swapBuffers() override { glfwSwapBuffers(window_); }
    void pollEvents() override { glfwPollEvents(); }
    void framebufferSize(int& width, int& height) const override { glfwGetFramebufferSize(window_, &width, &height); }
    void* nativeWindow() const override { return window_; }

private:
    GLFWwindow* window_ = nullptr;
};

}  // namespace

std::unique_ptr<WindowContext> createWindowContext(int width, int height, const std::string& title) {
    return std::make_unique<GlfwContext>(width, height, title);
}

}  // namespace eikon::gl
