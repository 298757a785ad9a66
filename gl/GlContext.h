// An OpenGL 4.5 core context, headless (EGL) or in a window (GLFW), behind
// one interface. Creating one makes it current on the calling thread.
#pragma once

#include <memory>
#include <string>

namespace eikon::gl {

struct GlInfo {
    std::string vendor;
    std::string renderer;
    std::string version;
    std::string glslVersion;
    std::string platform;  // how the context was made, e.g. "EGL surfaceless (Mesa)"
    // Limits that bound a scene: the largest storage buffer a shader reads
    // (camera images, sharp meshes), 2D and 3D texture edges (environment
    // maps, field grids), and the loop budget (loopBudgetForRenderer; 0: none).
    long long maxStorageBlockBytes = 0;
    int maxTextureSize = 0, max3dTextureSize = 0;
    unsigned loopBudget = 0;

    // Mesa's llvmpipe or softpipe: "GPU" work runs on the same CPU cores as
    // the simulation.
    bool rendersOnCpu() const {
        return renderer.find("llvmpipe") != std::string::npos || renderer.find("softpipe") != std::string::npos;
    }
};

// Loop iterations a shader invocation may run on a driver that caps them
// (0: no cap), for all its loops together. llvmpipe runs invocations in
// SIMD vectors of `bits`/32 lanes (its renderer string ends "(LLVM x, 256
// bits)") and ends every loop of a vector once the vector's loops have
// iterated LP_MAX_TGSI_LOOP_ITERATIONS = 65 535 times between them, leaving
// the invocation's state wherever it was. A vector iterates at most as
// often as its lanes do together, so a lane that keeps to 65 535 / lanes
// iterations is never cut short. Unknown widths count as 512 bits.
unsigned loopBudgetForRenderer(const std::string& renderer);
// The same for the current context.
unsigned currentLoopBudget();

class GlContext {
public:
    virtual ~GlContext() = default;
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    virtual void makeCurrent() = 0;
    const GlInfo& info() const { return info_; }

protected:
    GlContext() = default;
    // Reads vendor/renderer/version, checks for 4.5 core and the extensions
    // eikon needs, and installs the KHR_debug callback. Call once current.
    void initialiseCurrent(const std::string& platform);

private:
    GlInfo info_;
};

// Headless context through EGL. Tries, in order: the EGL device platform on a
// hardware device (NVIDIA and other GPU drivers), then Mesa's surfaceless
// platform (llvmpipe without a GPU). EIKON_EGL_PLATFORM=device|surfaceless
// forces one. Throws std::runtime_error naming every attempt when none gives
// an OpenGL 4.5 core context. `hardwareDevice`: the hardware devices are
// tried from this one on (modulo their count), so that the ranks of an MPI
// job on one machine take one GPU each (by local rank) where it has several.
std::unique_ptr<GlContext> createHeadlessContext(unsigned hardwareDevice = 0);

class WindowContext : public GlContext {
public:
    virtual bool shouldClose() const = 0;
    virtual void swapBuffers() = 0;
    virtual void pollEvents() = 0;
    virtual void framebufferSize(int& width, int& height) const = 0;
    virtual void* nativeWindow() const = 0;  // GLFWwindow*, for UI layers
};

// A window with an OpenGL 4.5 core context through GLFW.
std::unique_ptr<WindowContext> createWindowContext(int width, int height, const std::string& title);

}  // namespace eikon::gl
