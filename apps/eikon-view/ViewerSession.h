// What the viewer shows: a scene, its fields (static; moving meshes and water
// updated in host memory; or a fluid simulated frame by frame through the
// zero-copy ring, LiveFrames.h) and the frame renderer —
// the same pieces `eikon run` drives. The viewer changes the camera, the
// lights, the photon count and the exposure in place; anything else (a new
// scene file, panel edits of tracer, material or solver settings) builds a
// new session.
#pragma once

#include "apps/eikon/LiveFrames.h"
#include "bridge/scene/Scene.h"
#include "render/graph/FrameRenderer.h"
#include "sim/SceneFields.h"

#include <memory>

namespace eikon::view {

class ViewerSession {
public:
    explicit ViewerSession(const Scene& scene);

    const Scene& scene() const { return scene_; }
    render::FrameRenderer& renderer() { return *renderer_; }
    bool simulated() const { return fields_->changesOverTime(); }
    double simulatedTime() const { return live_ ? live_->current().time : fields_->time(); }

    // Renders the current frame; with `advance`, a simulated scene moves on
    // one frame (simulated during the render when `pipelined`).
    render::FrameResult renderFrame(bool advance, bool pipelined);

private:
    Scene scene_;
    std::unique_ptr<sim::SceneFields> fields_;
    std::unique_ptr<app::LiveFrames> live_;
    std::unique_ptr<render::FrameRenderer> renderer_;
};

}  // namespace eikon::view
