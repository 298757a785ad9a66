// eikon::View (include/eikon/eikon.h): the live viewer fed by the caller's
// loop — a window of its own, apart from the renderers' headless context,
// with eikon-view's camera gestures, panel and preview policy
// (apps/viewer/). It shows the renderer's frames through eikon-view's
// presenter (apps/common/ImagePresenter.h); when the user moves the camera
// or the light it re-renders the renderer's current fields itself, as a
// preview of one ray per k×k pixels while the camera moves and in full
// once it rests. Unlike eikon-view it keeps the scene's photon count while
// a light is dragged (each step retraces them all).
// A thread has one current context across EGL and GLX (libglvnd refuses a
// second): the view releases the renderers' EGL context before its
// window's and its window's after, and each renderer makes its own current
// again before its GL work, so the two take turns on the one thread.
#include "eikon/eikon.h"

#include "apps/common/ImagePresenter.h"
#include "apps/library/RendererImpl.h"
#include "apps/viewer/CameraControls.h"
#include "apps/viewer/ControlPanel.h"
#include "apps/viewer/StageTimes.h"
#include "apps/viewer/ViewPreview.h"
#include "bridge/scene/Orbit.h"
#include "gl/GlContext.h"
#include "io/image/ImageIo.h"

#include <epoxy/egl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>

namespace eikon {

namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

struct View::Impl {
    std::string title;
    int width = 0, height = 0;
    std::unique_ptr<gl::WindowContext> window;
    std::unique_ptr<view::ImagePresenter> presenter;  // of the window's context
    ImGuiContext* imgui = nullptr;
    std::unique_ptr<view::ControlPanel> panel;
    view::ViewPreview preview;
    view::ViewerStatus status;
    Orbit orbit;
    double exposureEv = 0.0;
    long long photons = 0;
    bool paused = false, pipelined = false;  // the panel's, for a scene that moves by itself: never here
    bool rerender = false;     // the panel changed what the frame shows: render it again at the next show()
    bool applyTracer = false;  // with the panel's tracer settings
    Clock::time_point opened, lastShow;
    int screenshots = 0;
    render::Image8 shown;  // the frame presented: a copy of the renderer's last
    bool closed = false;

    // The window's context current in place of a renderer's, and back to none.
    static void releaseRenderers() {
        if (eglGetCurrentContext() != EGL_NO_CONTEXT)
            eglMakeCurrent(eglGetCurrentDisplay(), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    }
    void enter() {
        releaseRenderers();
        window->makeCurrent();
        ImGui::SetCurrentContext(imgui);
    }
    static void leave() { glfwMakeContextCurrent(nullptr); }

    void open(const Renderer::Impl& renderer) {
        const render::Image8& frame = renderer.lastFrame().image;
        releaseRenderers();
        try {
            window = gl::createWindowContext(width ? width : frame.width, height ? height : frame.height, title);
        } catch (const std::runtime_error& error) {
            throw Error(std::string("eikon::View: expected a window, found none: ") + error.what());
        }
        presenter = std::make_unique<view::ImagePresenter>();
        imgui = ImGui::CreateContext();
        ImGui::SetCurrentContext(imgui);
        ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini next to the user's files
        ImGui_ImplGlfw_InitForOpenGL(static_cast<GLFWwindow*>(window->nativeWindow()), true);
        ImGui_ImplOpenGL3_Init("#version 450 core");
        panel = std::make_unique<view::ControlPanel>(renderer.renderScene);
        orbit = orbitOf(renderer.renderScene.camera);
        exposureEv = renderer.renderScene.render.exposureEv;
        photons = renderer.renderScene.render.photons;
        status.sceneName = title;
        opened = lastShow = Clock::now();
    }

    void close() {
        if (window) {
            enter();  // the presenter's and the panel's GL objects go with their context current
            ImGui_ImplOpenGL3_Shutdown();
            ImGui_ImplGlfw_Shutdown();
            ImGui::DestroyContext(imgui);
            imgui = nullptr;
        }
        presenter.reset();
        window.reset();
        leave();
    }
    ~Impl() { close(); }

    // The mouse's gestures as eikon-view reads them (apps/viewer/CameraControls.h):
    // left drag orbits, middle drag pans, the wheel zooms. The camera they
    // move to, none where they did not move it.
    std::optional<CameraDesc> movedCamera(const Renderer::Impl& renderer) {
        const ImGuiIO& io = ImGui::GetIO();
        if (io.WantCaptureMouse) return std::nullopt;
        int framebufferWidth = 0, framebufferHeight = 0;
        window->framebufferSize(framebufferWidth, framebufferHeight);
        const CameraDesc& camera = renderer.renderScene.camera;
        Orbit moved = orbit;
        if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) moved = view::orbitDrag(moved, io.MouseDelta.x, io.MouseDelta.y);
        if (ImGui::IsMouseDragging(ImGuiMouseButton_Middle))
            moved = view::panDrag(moved, camera, io.MouseDelta.x, io.MouseDelta.y, framebufferHeight);
        if (io.MouseWheel != 0.0f) moved = view::zoom(moved, io.MouseWheel);
        if (moved.target == orbit.target && moved.distance == orbit.distance && moved.azimuthDeg == orbit.azimuthDeg &&
            moved.elevationDeg == orbit.elevationDeg)
            return std::nullopt;
        orbit = moved;
        return cameraOn(orbit, camera);
    }

    // Right drag: the first light moves in its horizontal plane (a
    // directional one turns), as in eikon-view. Where it moved, the light.
    std::optional<LightDesc> movedLight(const Renderer::Impl& renderer) const {
        const ImGuiIO& io = ImGui::GetIO();
        if (io.WantCaptureMouse || renderer.renderScene.lights.empty() ||
            !ImGui::IsMouseDragging(ImGuiMouseButton_Right) || (io.MouseDelta.x == 0.0f && io.MouseDelta.y == 0.0f))
            return std::nullopt;
        int framebufferWidth = 0, framebufferHeight = 0;
        window->framebufferSize(framebufferWidth, framebufferHeight);
        return view::lightDrag(renderer.renderScene.lights[0], renderer.renderScene.camera, io.MouseDelta.x,
                               io.MouseDelta.y, framebufferHeight);
    }

    // What the window's events changed, given to the renderer (the window's
    // context released: the renderer's own takes them), and its current
    // fields rendered again where the picture changed; the view pass's time
    // told to the preview policy.
    void renderAgain(Renderer& renderer, Renderer::Impl& state, const std::optional<CameraDesc>& camera,
                     const std::optional<LightDesc>& light, int stride) {
        const bool again = camera || light || rerender || state.lastFrame().pixelStride != stride;
        if (!again && stride == state.pixelStride) return;
        leave();
        if (camera) state.setCamera(*camera);
        if (light) state.setLight(0, *light);
        if (exposureEv != state.renderScene.render.exposureEv) state.setExposure(exposureEv);
        if (photons != state.renderScene.render.photons) state.setPhotonCount(photons);
        if (applyTracer) {
            state.scene.tracer = state.renderScene.tracer = panel->edited().tracer;
            state.source.reset();  // made again by the render, with the tracer applied
            applyTracer = false;
        }
        if (stride != state.pixelStride) state.setPixelStride(stride);
        if (again) {
            renderer.render();
            const render::FrameResult& frame = state.lastFrame();
            preview.measured(frame.pixelStride,
                             view::stageMilliseconds(frame, view::pictureStage(state.renderScene.diagnostic.has_value())),
                             frame.pixelStride > 1 ? 1 : frame.viewSamples);
        }
        rerender = false;
        enter();
    }

    // The panel's requests, taken at the next show(): exposure and photons
    // at once, the tracer's settings by a frame renderer made anew; a
    // screenshot is the frame's PNG under out/<title>/, as eikon-view
    // writes one.
    void act(const view::PanelRequests& requests, const Renderer::Impl& renderer) {
        if (exposureEv != renderer.renderScene.render.exposureEv || photons != renderer.renderScene.render.photons)
            rerender = true;
        if (requests.apply) {
            applyTracer = rerender = true;
            status.message = "tracer settings applied (materials come with the caller's fields)";
        }
        if (requests.screenshot) {
            const std::filesystem::path folder = std::filesystem::path("out") / title;
            std::filesystem::create_directories(folder);
            char name[32];
            std::snprintf(name, sizeof name, "screenshot_%04d.png", screenshots++);
            io::writePng(folder / name, shown.width, shown.height, shown.rgba);
            status.message = "wrote " + (folder / name).string();
        }
    }

    // The frame into the window's back buffer, the window's context current.
    void present() {
        int framebufferWidth = 0, framebufferHeight = 0;
        window->framebufferSize(framebufferWidth, framebufferHeight);
        presenter->present(shown, framebufferWidth, framebufferHeight);
    }
};

View::View(std::string title, int width, int height) : impl_(std::make_unique<Impl>()) {
    if (width < 0 || height < 0)
        throw Error("eikon::View: expected a window size of 0 (the first frame's) or more pixels, found " +
                    std::to_string(width) + " × " + std::to_string(height));
    impl_->title = std::move(title);
    impl_->width = width;
    impl_->height = height;
}
View::~View() = default;
View::View(View&&) noexcept = default;
View& View::operator=(View&&) noexcept = default;

bool View::show(Renderer& renderer) {
    Impl& impl = *impl_;
    if (impl.closed) return false;
    Renderer::Impl& state = *renderer.impl_;
    state.lastFrame();  // Error before the first frame
    if (!impl.window) impl.open(state);
    impl.enter();
    impl.window->pollEvents();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    const Clock::time_point now = Clock::now();
    const std::optional<CameraDesc> camera = impl.movedCamera(state);
    const int stride =
        impl.preview.strideFor(camera.has_value(), std::chrono::duration<double>(now - impl.opened).count());
    impl.renderAgain(renderer, state, camera, impl.movedLight(state), stride);
    impl.shown = state.lastFrame().image;
    impl.present();
    const double ms = std::chrono::duration<double, std::milli>(now - impl.lastShow).count();
    impl.lastShow = now;
    impl.status.framesPerSecond = 0.9 * impl.status.framesPerSecond + 0.1 * 1000.0 / std::max(ms, 1e-3);
    impl.status.photonsInUse = impl.photons;
    const view::PanelRequests requests =
        impl.panel->draw(state.lastFrame(), impl.status, impl.paused, impl.pipelined, impl.exposureEv, impl.photons);
    impl.act(requests, state);
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    impl.window->swapBuffers();
    if (impl.window->shouldClose()) {
        impl.closed = true;
        impl.close();
    }
    Impl::leave();
    return !impl.closed;
}

bool View::isOpen() const { return !impl_->closed; }

ByteArray View::windowImage() const {
    Impl& impl = *impl_;
    if (!impl.window) throw Error("eikon::View::windowImage: expected a window shown (call show()), found none");
    impl.enter();
    impl.present();  // again, into the back buffer (without the panel), which is read before any swap
    int width = 0, height = 0;
    impl.window->framebufferSize(width, height);
    const auto w = static_cast<std::size_t>(width), h = static_cast<std::size_t>(height);
    std::vector<std::uint8_t> rgba(w * h * 4);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    ByteArray array{{h, w, 3}, std::vector<std::uint8_t>(w * h * 3)};
    for (std::size_t y = 0; y < h; ++y)  // GL's row 0 is the bottom
        for (std::size_t x = 0; x < w; ++x)
            for (std::size_t c = 0; c < 3; ++c)
                array.values[(y * w + x) * 3 + c] = rgba[((h - 1 - y) * w + x) * 4 + c];
    Impl::leave();
    return array;
}

}  // namespace eikon
