#include "gl/GlContext.h"

#include "gl/GlDebug.h"
#include "gl/GpuMemory.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <regex>
#include <stdexcept>
#include <string>

namespace eikon::gl {

namespace {

std::string glString(GLenum name) {
    const auto* text = reinterpret_cast<const char*>(glGetString(name));
    return text ? text : "(unknown)";
}

}  // namespace

unsigned loopBudgetForRenderer(const std::string& renderer) {
    if (renderer.find("llvmpipe") == std::string::npos) return 0;
    static const std::regex width(R"((\d+) bits\))");
    std::smatch match;
    const int bits = std::regex_search(renderer, match, width) ? std::stoi(match[1].str()) : 512;
    constexpr unsigned kLlvmpipeLoopIterations = 65535;
    return kLlvmpipeLoopIterations / static_cast<unsigned>(std::max(1, bits / 32));
}

unsigned currentLoopBudget() { return loopBudgetForRenderer(glString(GL_RENDERER)); }

void GlContext::initialiseCurrent(const std::string& platform) {
    info_.vendor = glString(GL_VENDOR);
    info_.renderer = glString(GL_RENDERER);
    info_.version = glString(GL_VERSION);
    info_.glslVersion = glString(GL_SHADING_LANGUAGE_VERSION);
    info_.platform = platform;
    GLint64 storage = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &storage);
    info_.maxStorageBlockBytes = storage;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &info_.maxTextureSize);
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &info_.max3dTextureSize);
    info_.loopBudget = loopBudgetForRenderer(info_.renderer);
    setGpuMemoryLimit(queryGpuMemoryLimit(info_.renderer, info_.rendersOnCpu()));
    if (epoxy_gl_version() < 45)
        throw std::runtime_error(platform + " gave OpenGL " + info_.version + " on " + info_.renderer +
                                 "; eikon needs OpenGL 4.5 core");
    // Photon deposition accumulates power with float atomics.
    if (!epoxy_has_gl_extension("GL_NV_shader_atomic_float"))
        throw std::runtime_error(platform + ": " + info_.renderer +
                                 " lacks GL_NV_shader_atomic_float, which photon deposition needs");
    installDebugCallback();
}

}  // namespace eikon::gl
