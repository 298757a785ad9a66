// Headless OpenGL through EGL: the device platform for GPU drivers, Mesa's
// surfaceless platform (llvmpipe) when there is no GPU.
#include "gl/GlContext.h"

#include <epoxy/egl.h>

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace eikon::gl {

namespace {

class EglContext final : public GlContext {
public:
    EglContext(EGLDisplay display, EGLContext context, const std::string& platform)
        : display_(display), context_(context) {
        makeCurrent();
        initialiseCurrent(platform);
    }
    ~EglContext() override {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }
    void makeCurrent() override {
        if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
            throw std::runtime_error("eglMakeCurrent failed");
    }

private:
    EGLDisplay display_;
    EGLContext context_;
};

std::string eglErrorText() {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", eglGetError());
    return std::string("EGL error ") + code;
}

// Initialises `display` and creates a 4.5 core context on it without a
// surface. Returns nullptr and appends to `attempts` on failure.
std::unique_ptr<GlContext> contextOn(EGLDisplay display, const std::string& platform,
                                     std::vector<std::string>& attempts) {
    EGLint major = 0, minor = 0;
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) {
        attempts.push_back(platform + ": no display (" + eglErrorText() + ")");
        return nullptr;
    }
    const char* extensions = eglQueryString(display, EGL_EXTENSIONS);
    if (!extensions || std::string(extensions).find("EGL_KHR_surfaceless_context") == std::string::npos) {
        attempts.push_back(platform + ": no EGL_KHR_surfaceless_context");
        eglTerminate(display);
        return nullptr;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        attempts.push_back(platform + ": cannot bind the OpenGL API (" + eglErrorText() + ")");
        eglTerminate(display);
        return nullptr;
    }
    const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configCount = 0;
    eglChooseConfig(display, configAttributes, &config, 1, &configCount);  // may be 0: use no config
    std::vector<EGLint> contextAttributes = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                             EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT};
#ifndef NDEBUG
    contextAttributes.insert(contextAttributes.end(), {EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE});
#endif
    contextAttributes.push_back(EGL_NONE);
    EGLContext context = eglCreateContext(display, configCount > 0 ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT,
                                          contextAttributes.data());
    if (context == EGL_NO_CONTEXT) {
        attempts.push_back(platform + ": no OpenGL 4.5 core context (" + eglErrorText() + ")");
        eglTerminate(display);
        return nullptr;
    }
    try {
        return std::make_unique<EglContext>(display, context, platform);
    } catch (const std::exception& error) {
        attempts.push_back(error.what());
        // The constructor threw, so no destructor runs: release here.
        eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display, context);
        eglTerminate(display);
        return nullptr;
    }
}

bool clientHas(const char* extension) { return epoxy_has_egl_extension(EGL_NO_DISPLAY, extension); }

std::unique_ptr<GlContext> tryDevicePlatform(unsigned firstDevice, std::vector<std::string>& attempts) {
    if (!clientHas("EGL_EXT_platform_device") || !clientHas("EGL_EXT_device_enumeration")) {
        attempts.push_back("EGL device platform: not offered by this EGL");
        return nullptr;
    }
    EGLint count = 0;
    eglQueryDevicesEXT(0, nullptr, &count);
    std::vector<EGLDeviceEXT> devices(static_cast<size_t>(count));
    eglQueryDevicesEXT(count, devices.data(), &count);
    std::vector<EGLint> hardware;
    for (EGLint i = 0; i < count; ++i) {
        const char* deviceExtensions = eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS);
        // Software devices are reached through the surfaceless platform instead.
        if (!deviceExtensions || std::string(deviceExtensions).find("EGL_MESA_device_software") == std::string::npos)
            hardware.push_back(i);
    }
    for (std::size_t k = 0; k < hardware.size(); ++k) {
        const EGLint i = hardware[(firstDevice + k) % hardware.size()];
        const std::string name = "EGL device platform, device " + std::to_string(i);
        EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (auto context = contextOn(display, name, attempts)) return context;
    }
    if (count == 0) attempts.push_back("EGL device platform: no devices");
    else attempts.push_back("EGL device platform: no hardware device gave a context");
    return nullptr;
}

std::unique_ptr<GlContext> trySurfacelessPlatform(std::vector<std::string>& attempts) {
    if (!clientHas("EGL_MESA_platform_surfaceless")) {
        attempts.push_back("EGL surfaceless platform (Mesa): not offered by this EGL");
        return nullptr;
    }
    EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    return contextOn(display, "EGL surfaceless platform (Mesa)", attempts);
}

}  // namespace

std::unique_ptr<GlContext> createHeadlessContext(unsigned hardwareDevice) {
    std::vector<std::string> attempts;
    const char* forced = std::getenv("EIKON_EGL_PLATFORM");
    const std::string choice = forced ? forced : "";
    if (!choice.empty() && choice != "device" && choice != "surfaceless")
        throw std::runtime_error("EIKON_EGL_PLATFORM: expected device or surfaceless, found '" + choice + "'");
    if (choice != "surfaceless")
        if (auto context = tryDevicePlatform(hardwareDevice, attempts)) return context;
    if (choice != "device")
        if (auto context = trySurfacelessPlatform(attempts)) return context;
    std::string message = "no headless OpenGL 4.5 core context could be made; tried:";
    for (const auto& attempt : attempts) message += "\n  - " + attempt;
    message += "\nOn a machine without a GPU, install Mesa's EGL driver (libegl-mesa0, libgl1-mesa-dri).";
    throw std::runtime_error(message);
}

}  // namespace eikon::gl
