#include "apps/eikon-view/Viewer.h"

#include "apps/common/FollowedVolume.h"
#include "apps/viewer/CameraControls.h"
#include "apps/viewer/ControlPanel.h"
#include "apps/common/ImagePresenter.h"
#include "apps/eikon-view/SimulationPacer.h"
#include "apps/viewer/StageTimes.h"
#include "apps/viewer/ViewPreview.h"
#include "apps/eikon-view/ViewerSession.h"
#include "bridge/core/Error.h"
#include "io/image/ImageIo.h"
#include "io/scene/SceneParser.h"
#include "gl/GlContext.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace eikon::view {

namespace {

using Clock = std::chrono::steady_clock;

std::filesystem::file_time_type modificationTime(const std::string& path) {
    std::error_code error;
    const auto time = std::filesystem::last_write_time(path, error);
    return error ? std::filesystem::file_time_type{} : time;
}

// The scene file with --set applied and, with --follow, its volume followed.
Scene loadScene(const ViewerOptions& options) {
    Scene scene = loadSceneFile(options.scenePath, options.overrides);
    if (options.follow) app::followVolume(scene, {options.followPollMs / 1000.0, options.followTimeoutS, ""});
    return scene;
}

class Viewer {
public:
    explicit Viewer(const ViewerOptions& options)
        : options_(options),
          scene_(loadScene(options)),
          window_(gl::createWindowContext(options.width, options.height, "eikon-view — " + options.scenePath)),
          panel_(scene_),
          preview_(PreviewSettings{options.previewViewMs}),
          pacer_(options.cameraFrameMs),
          sceneTime_(modificationTime(options.scenePath)) {
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini next to the user's files
        ImGui_ImplGlfw_InitForOpenGL(static_cast<GLFWwindow*>(window_->nativeWindow()), true);
        ImGui_ImplOpenGL3_Init("#version 450 core");
        start(scene_);
        status_.sceneName = std::filesystem::path(options.scenePath).filename().string();
        pipelined_ = !window_->info().rendersOnCpu();
    }

    ~Viewer() {
        session_.reset();  // GL objects go before the context
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    }

    int run() {
        const auto viewerStart = Clock::now();
        auto runStart = viewerStart;  // from the end of the first frame: steady state
        double scriptedSeconds = 0.0;
        while (!window_->shouldClose()) {
            window_->pollEvents();
            const auto frameStart = Clock::now();
            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            ImGui::NewFrame();
            const bool cameraMoved = handleInput();
            const double now = std::chrono::duration<double>(frameStart - viewerStart).count();
            const int stride = preview_.strideFor(cameraMoved, now);
            const bool cameraMoving = preview_.cameraMoving(now);  // or came to rest within the refine delay
            const bool running = session_->simulated() && !paused_;
            bool advance = (running && pacer_.advances(cameraMoving)) || (session_->simulated() && stepOnce_);
            // A followed simulation moves on only when its next step is complete.
            if (advance && session_->following()) advance = session_->nextStepReady();
            // While the camera moves, an advance the pacer asks of a CPU
            // solver is produced in the background and shown once ready: the
            // camera never waits for a solver step.
            const bool shownFromBackground = session_->showBackgroundAdvance();
            if (session_->advancingInBackground()) {
                advance = false;
            } else if (advance && cameraMoving && session_->canAdvanceInBackground()) {
                session_->beginBackgroundAdvance();
                advance = false;
            }
            const bool advanced = advance || shownFromBackground;
            stepOnce_ = false;
            // While the camera moves, a scene of surfaces shows its image-space
            // preview; others (and at rest, every scene) the eikonal frame.
            const bool imageSpacePreview = stride > 1 && session_->hasImageSpacePreview();
            const char* picture = pictureStage(session_->scene().diagnostic.has_value());
            if (imageSpacePreview) {
                const int scale = preview_.imageSpaceScale();
                last_ = session_->renderImageSpacePreview(advance, scale);
                preview_.measuredImageSpace(scale, stageMilliseconds(last_, "image_space_view"));
                largestImageSpaceScale_ = std::max(largestImageSpaceScale_, scale);
            } else {
                session_->renderer().setPixelStride(stride);
                last_ = session_->renderFrame(advance, pipelined_);
                preview_.measured(last_.pixelStride, stageMilliseconds(last_, picture),
                                  last_.pixelStride > 1 ? 1 : last_.viewSamples);
            }
            const double viewMs = stageMilliseconds(last_, imageSpacePreview ? "image_space_view" : picture);
            const bool previewed = last_.pixelStride > 1 || imageSpacePreview;
            if (viewMs > 0.0 && previewed && scripted()) {
                ++previewFrames_;
                imageSpacePreviews_ += imageSpacePreview ? 1 : 0;
                largestStride_ = std::max(largestStride_, last_.pixelStride);
                advancedFrames_ += advanced ? 1 : 0;
            }
            if (advance && session_->following()) noteSkippedSteps();
            adaptPhotons(cameraMoving);
            if (!last_.image.rgba.empty()) image_ = last_.image;
            int width = 0, height = 0;
            window_->framebufferSize(width, height);
            presenter_.present(image_, width, height);
            status_.simulated = session_->simulated();
            status_.simulatedTime = session_->simulatedTime();
            status_.solverDevice = session_->solverDevice();
            status_.waterDevice = session_->waterDevice();
            status_.photonsInUse = photons_;
            status_.imageSpacePreview = imageSpacePreview;
            status_.simulationHeld = running && !advanced && !session_->advancingInBackground();
            const PanelRequests requests = panel_.draw(last_, status_, paused_, pipelined_, exposure_, fullPhotons_);
            act(requests);
            ImGui::Render();
            ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
            // A scripted run ends on its full image: after its frames, and
            // back at the scene's camera with orbit-return, it waits for the
            // preview to refine.
            const bool lastFrame = options_.frames > 0 && rendered_ + 1 >= options_.frames && !imageSpacePreview &&
                                   last_.pixelStride == 1 && (options_.animate != "orbit-return" || returned_);
            if (lastFrame && !options_.windowShotPath.empty()) saveWindow(options_.windowShotPath, width, height);
            window_->swapBuffers();
            reloadIfChanged();
            const double ms = std::chrono::duration<double, std::milli>(Clock::now() - frameStart).count();
            status_.framesPerSecond = 0.9 * status_.framesPerSecond + 0.1 * 1000.0 / std::max(ms, 1e-3);
            // A session's first frame compiles its shaders: no measure of a frame.
            // A background advance is measured from the frame that shows it.
            if (running && !sessionStarting_) pacer_.frameDone(advanced, cameraMoving, ms);
            sessionStarting_ = false;
            if (rendered_ >= 1 && rendered_ < options_.frames) longestFrameMs_ = std::max(longestFrameMs_, ms);
            if (rendered_ < std::max(options_.frames, 1)) {
                if (++rendered_ == 1) runStart = Clock::now();
                if (rendered_ == options_.frames)
                    scriptedSeconds = std::chrono::duration<double>(Clock::now() - runStart).count();
            }
            if (lastFrame) {
                if (!options_.screenshotPath.empty()) saveImage(options_.screenshotPath);
                if (!options_.animate.empty())
                    std::printf("eikon-view: %s: %d frames after the first in %.2f s, %.2f frames/s, last photon "
                                "count %lld, %d previews (%d in image space, at up to 1/%d size; pixel stride up to %d), "
                                "%d of them advanced the scene, longest frame %.0f ms\n",
                                options_.animate.c_str(), rendered_ - 1, scriptedSeconds,
                                (rendered_ - 1) / scriptedSeconds, photons_, previewFrames_, imageSpacePreviews_,
                                largestImageSpaceScale_, largestStride_, advancedFrames_, longestFrameMs_);
                break;
            }
        }
        return 0;
    }

private:
    void start(const Scene& scene) {
        session_.reset();
        session_ = std::make_unique<ViewerSession>(scene, !window_->info().rendersOnCpu());
        pacer_ = SimulationPacer(options_.cameraFrameMs);
        sessionStarting_ = true;
        orbit_ = orbitOf(scene.camera);
        exposure_ = scene.render.exposureEv;
        fullPhotons_ = photons_ = scene.render.photons;
        panel_.reset(scene);
    }

    // Whether scripted input (--animate) still runs: for --frames frames, or for ever.
    bool scripted() const { return !options_.animate.empty() && (options_.frames == 0 || rendered_ < options_.frames); }

    // Mouse, keys and scripted input; returns whether the camera moved.
    bool handleInput() {
        const ImGuiIO& io = ImGui::GetIO();
        int width = 0, height = 0;
        window_->framebufferSize(width, height);
        render::FrameRenderer& renderer = session_->renderer();
        const CameraDesc& camera = renderer.scene().camera;
        draggingLight_ = false;
        bool cameraMoved = false;
        const bool orbiting = scripted() && (options_.animate == "orbit" || options_.animate == "orbit-return");
        if (!scripted() && options_.animate == "orbit-return" && !returned_) {
            // Back to the scene's own camera, exactly (tests compare the
            // refined frame with the headless render).
            returned_ = true;
            renderer.setCamera(session_->scene().camera);
            orbit_ = orbitOf(session_->scene().camera);
            cameraMoved = true;
        }
        if (!io.WantCaptureMouse) {
            Orbit orbit = orbit_;
            if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) orbit = orbitDrag(orbit, io.MouseDelta.x, io.MouseDelta.y);
            if (orbiting) orbit = orbitDrag(orbit, 6.0, 0.0);
            if (ImGui::IsMouseDragging(ImGuiMouseButton_Middle))
                orbit = panDrag(orbit, camera, io.MouseDelta.x, io.MouseDelta.y, height);
            if (io.MouseWheel != 0.0f) orbit = zoom(orbit, io.MouseWheel);
            if (orbit.target != orbit_.target || orbit.distance != orbit_.distance ||
                orbit.azimuthDeg != orbit_.azimuthDeg || orbit.elevationDeg != orbit_.elevationDeg) {
                orbit_ = orbit;
                renderer.setCamera(cameraOn(orbit_, camera));
                cameraMoved = true;
            }
            if (ImGui::IsMouseDragging(ImGuiMouseButton_Right) && !renderer.scene().lights.empty()) {
                draggingLight_ = true;
                if (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)
                    renderer.setLight(0, lightDrag(renderer.scene().lights[0], camera, io.MouseDelta.x,
                                                   io.MouseDelta.y, height));
            }
            if (scripted() && options_.animate == "light" && !renderer.scene().lights.empty()) {
                draggingLight_ = true;
                renderer.setLight(0, lightDrag(renderer.scene().lights[0], camera, 6.0, 0.0, height));
            }
        }
        if (!io.WantCaptureKeyboard) {
            if (ImGui::IsKeyPressed(GLFW_KEY_SPACE, false)) paused_ = !paused_;
            if (ImGui::IsKeyPressed(GLFW_KEY_N, false)) stepOnce_ = true;
            if (ImGui::IsKeyPressed(GLFW_KEY_R, false)) start(session_->scene());
            if (ImGui::IsKeyPressed(GLFW_KEY_P, false)) screenshot();
        }
        renderer.setExposure(exposure_);
        return cameraMoved;
    }

    // While photons are retraced every frame — a light dragged, or a scene
    // that moves — fewer of them keep the target frame time, the new count
    // taking effect at the next trace (frames that hold the scene while the
    // camera moves trace none); when the light is let go or the scene
    // paused, the full count traces once more (progressive).
    // While the camera moves, a trace (for a scene's advance) keeps to the
    // camera's frame time where that is the shorter: it is the frame the
    // camera waits for.
    void adaptPhotons(bool cameraMoving) {
        render::FrameRenderer& renderer = session_->renderer();
        long long wanted = fullPhotons_;
        const bool retracingEveryFrame = draggingLight_ || (session_->simulated() && !paused_);
        if (retracingEveryFrame) {
            const double ms = stageMilliseconds(last_, "photons");
            if (ms > 0.0) {
                const double target = cameraMoving && options_.cameraFrameMs > 0.0
                                          ? std::min(options_.targetFrameMs, options_.cameraFrameMs)
                                          : options_.targetFrameMs;
                const double scale = std::clamp(target / ms, 1.0 / 16.0, 2.0);
                wanted = std::clamp(static_cast<long long>(static_cast<double>(photons_) * scale), 4096LL, fullPhotons_);
            } else {
                wanted = photons_;
            }
        }
        photons_ = wanted;
        renderer.setPhotonCount(photons_, !retracingEveryFrame);
    }

    void act(const PanelRequests& requests) {
        if (requests.step) stepOnce_ = true;
        if (requests.reset) start(session_->scene());
        if (requests.screenshot) screenshot();
        if (requests.apply) {
            Scene edited = panel_.edited();
            edited.camera = session_->renderer().scene().camera;
            edited.lights = session_->renderer().scene().lights;
            edited.render.exposureEv = exposure_;
            edited.render.photons = fullPhotons_;
            rebuild(edited, "settings applied");
        }
    }

    void rebuild(const Scene& scene, const std::string& note) {
        try {
            start(scene);
            status_.message = note;
        } catch (const InputError& error) {
            status_.message = std::string("not applied: ") + error.what();
            start(scene_);
        }
        scene_ = session_->scene();
    }

    void reloadIfChanged() {
        const auto now = Clock::now();
        if (now - lastReloadCheck_ < std::chrono::milliseconds(500)) return;
        lastReloadCheck_ = now;
        const auto time = modificationTime(options_.scenePath);
        if (time == sceneTime_) return;
        sceneTime_ = time;
        try {
            const Scene reloaded = loadScene(options_);
            rebuild(reloaded, "reloaded " + options_.scenePath);
        } catch (const InputError& error) {
            status_.message = std::string("reload failed, keeping the last scene: ") + error.what();
        }
    }

    // The panel's message names the damaged steps a followed simulation's
    // new step was found past.
    void noteSkippedSteps() {
        const std::vector<sim::SkippedStep> skipped = session_->skippedBefore();
        if (skipped.empty()) return;
        status_.message = "skipped " + std::to_string(skipped.size()) + " damaged step(s) before " +
                          session_->followedStep() + ": " + skipped.front().reason;
        for (const sim::SkippedStep& step : skipped)
            std::fprintf(stderr, "eikon-view: warning: skipped step %s: %s\n", step.step.c_str(), step.reason.c_str());
    }

    void saveImage(const std::filesystem::path& path) {
        io::writePng(path, image_.width, image_.height, image_.rgba);
        status_.message = "wrote " + path.string();
    }

    // The default framebuffer as the user sees it (bottom row first in GL).
    void saveWindow(const std::filesystem::path& path, int width, int height) {
        std::vector<std::uint8_t> pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glReadBuffer(GL_BACK);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
        const std::size_t row = static_cast<std::size_t>(width) * 4;
        std::vector<std::uint8_t> flipped(pixels.size());
        for (int y = 0; y < height; ++y)
            std::copy_n(pixels.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(height - 1 - y)),
                        row, flipped.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y)));
        io::writePng(path, width, height, flipped);
    }

    void screenshot() {
        const std::filesystem::path folder =
            std::filesystem::path("out") / std::filesystem::path(options_.scenePath).stem();
        std::filesystem::create_directories(folder);
        char name[32];
        std::snprintf(name, sizeof name, "screenshot_%04d.png", screenshots_++);
        saveImage(folder / name);
    }

    ViewerOptions options_;
    Scene scene_;
    std::unique_ptr<gl::WindowContext> window_;
    ImagePresenter presenter_;
    ControlPanel panel_;
    ViewPreview preview_;
    SimulationPacer pacer_;
    bool sessionStarting_ = true;  // the next frame is the session's first
    std::unique_ptr<ViewerSession> session_;
    render::FrameResult last_;
    render::Image8 image_;
    ViewerStatus status_;
    Orbit orbit_;
    double exposure_ = 0.0;
    long long fullPhotons_ = 0, photons_ = 0;
    bool paused_ = false, stepOnce_ = false, pipelined_ = false, draggingLight_ = false;
    int screenshots_ = 0;
    int rendered_ = 0;  // frames drawn, counted up to options_.frames
    int previewFrames_ = 0, imageSpacePreviews_ = 0, largestStride_ = 1;  // previews among the scripted frames
    int largestImageSpaceScale_ = 1;
    int advancedFrames_ = 0;  // previews among the scripted frames that advanced a moving scene
    double longestFrameMs_ = 0.0;  // among the scripted frames after the first
    bool returned_ = false;  // orbit-return: back at the scene's camera
    std::filesystem::file_time_type sceneTime_;
    Clock::time_point lastReloadCheck_ = Clock::now();
};

}  // namespace

int runViewer(const ViewerOptions& options) { return Viewer(options).run(); }

}  // namespace eikon::view
