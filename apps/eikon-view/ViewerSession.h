// What the viewer shows: a scene, its fields and the frame renderer, fed by
// the same frame source as `eikon run` (apps/common/FrameSource.h). The
// viewer changes the camera, the lights, the photon count and the exposure in
// place; anything else (a new scene file, panel edits of tracer, material or
// solver settings) builds a new session. A scene of surfaces alone that
// renders eikonally also gets an image-space renderer of itself
// (render.method "image_space"), which the viewer draws while the camera
// moves: a preview at raster speed, refined to the eikonal frame at rest.
#pragma once

#include "apps/common/FrameSource.h"
#include "bridge/scene/Scene.h"
#include "render/graph/FrameRenderer.h"
#include "sim/SceneFields.h"

#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace eikon::view {

class ViewerSession {
public:
    // `hardwareGpu`: the window's context is not a software rasterizer, so
    // sim.device "auto" runs the fluid solver there (SceneFields::placeFluidSolver).
    ViewerSession(const Scene& scene, bool hardwareGpu);

    const Scene& scene() const { return scene_; }
    render::FrameRenderer& renderer() { return source_->renderer(); }
    bool simulated() const { return fields_->changesOverTime(); }
    double simulatedTime() const { return source_->current().time; }
    std::string solverDevice() const { return fields_->fluidDevice(); }
    std::string waterDevice() const { return fields_->waterDevice(); }

    // Following a simulation (`--follow`): whether its next step is complete
    // and read, looked for at most once per follow.pollSeconds, without
    // waiting (sim/volume/VolumeFollower.h); the frame that advances shows it.
    bool following() const { return followed_ != nullptr; }
    bool nextStepReady();
    // The step the current frame shows, and the damaged steps skipped before it.
    std::string followedStep() const;
    std::vector<sim::SkippedStep> skippedBefore() const;

    // Renders the current frame; with `advance`, a simulated scene moves on
    // one frame (simulated during the render when `pipelined`).
    render::FrameResult renderFrame(bool advance, bool pipelined);
    // While the camera moves, a solver on the CPU advances in the background:
    // its next frame is produced on a thread while the viewer draws the
    // current one, and shown once ready, so that the camera never waits
    // for a solver step. Only where no light is traced (a diagnostic, a
    // view without receivers or scattering): there the step is what the
    // camera waited for, while a light pass after each advance runs on this
    // thread either way and a solver beside it only takes cores from it
    // (an orbit of syrup_mixing 10–15% slower on two cores). Not for a
    // solver on the GPU (it queues its passes on this context) nor a
    // followed simulation (read as it is written).
    bool canAdvanceInBackground() const;
    void beginBackgroundAdvance();
    bool advancingInBackground() const { return advancingInBackground_; }
    // Once the background frame is ready (nothing waits): makes it current,
    // and returns true; the next render draws it.
    bool showBackgroundAdvance();
    // Whether the scene has an image-space preview (all surfaces, drawn eikonally).
    bool hasImageSpacePreview() const { return imageSpaceScene_.has_value(); }
    // The image-space frame of the current fields, seen by the eikonal
    // renderer's camera under its lights, at 1/scale of the image's size in
    // each direction; with `advance`, a moving scene then moves on one frame.
    render::FrameResult renderImageSpacePreview(bool advance, int scale);

private:
    Scene scene_;
    std::unique_ptr<sim::SceneFields> fields_;
    std::unique_ptr<app::FrameSource> source_;
    sim::VolumeSequence* followed_ = nullptr;
    bool advancingInBackground_ = false;
    std::chrono::steady_clock::time_point lastLook_{};
    std::optional<Scene> imageSpaceScene_;  // the scene as its image-space preview draws it
    std::map<int, std::unique_ptr<render::FrameRenderer>> imageSpace_;  // by scale, made when first drawn
};

}  // namespace eikon::view
