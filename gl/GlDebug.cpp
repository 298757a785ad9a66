#include "gl/GlDebug.h"

#include <epoxy/gl.h>

#include <stdexcept>

namespace eikon::gl {

#ifndef NDEBUG
namespace {

thread_local std::string pendingDebugError;

void GLAPIENTRY onDebugMessage(GLenum, GLenum type, GLuint, GLenum severity, GLsizei, const GLchar* message,
                               const void*) {
    const bool isError = type == GL_DEBUG_TYPE_ERROR || severity == GL_DEBUG_SEVERITY_HIGH;
    if (isError && pendingDebugError.empty()) pendingDebugError = message;
}

}  // namespace
#endif

void installDebugCallback() {
#ifndef NDEBUG
    if (!epoxy_has_gl_extension("GL_KHR_debug")) return;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, nullptr);
#endif
}

void checkpoint(const std::string& where) {
    const GLenum error = glGetError();
    std::string message;
#ifndef NDEBUG
    std::swap(message, pendingDebugError);
#endif
    if (error == GL_NO_ERROR && message.empty()) return;
    if (message.empty()) message = "glGetError() = " + std::to_string(error);
    throw std::runtime_error("OpenGL error in " + where + ": " + message);
}

}  // namespace eikon::gl
