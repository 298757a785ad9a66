// Where the renderer's fields come from, frame after frame — the one place
// that decides between host memory and the GPU field ring, for `eikon run`
// and the viewer alike. A scene with a fluid solver goes through the
// zero-copy ring (LiveFrames.h): the next frame is simulated into its slot
// while the current one renders (when pipelined) or after it. Any other
// scene keeps its fields in host memory: a static scene is uploaded once,
// moving meshes and water are recomputed where they moved and uploaded as
// they change — except a water body the GPU simulates
// (sim/gpu/GpuWaterBody.h), whose surface and attenuation come from its
// own buffers and never cross the bus.
//
// One turn of a loop: beginNext() (when a next frame follows), render(),
// waitNext(), write the current frame's outputs from currentViews(), then
// publishNext(). Host fields advance in publishNext(), after the outputs,
// since they are overwritten in place.
#pragma once

#include "apps/common/LiveFrames.h"
#include "bridge/grid/FieldViews.h"
#include "bridge/scene/Scene.h"
#include "render/graph/FrameRenderer.h"
#include "sim/SceneFields.h"

#include <memory>

namespace eikon::app {

class FrameSource {
public:
    // Each frame `exports` exports keeps what export reads of it (the
    // solver's own fields it asks for, the deformed meshes) as it was produced.
    FrameSource(const Scene& scene, sim::SceneFields& fields, const render::RendererOptions& options,
                bool pipelined, ExportNeeds exports);

    render::FrameRenderer& renderer() { return *renderer_; }
    const render::FrameRenderer& renderer() const { return *renderer_; }
    bool throughRing() const { return live_ != nullptr; }
    // Takes effect at the next beginNext() (ring only; host fields are never pipelined).
    void setPipelined(bool pipelined);

    // Ring: acquires the next slot and, when pipelined, starts simulating into it.
    void beginNext();
    // Renders the current frame.
    render::FrameResult render();
    // The current frame's fields as a renderer takes them, for another
    // renderer of the same scene (the viewer's preview); host fields only.
    render::FieldUpload hostFields() const;
    // Ring: whether waitNext() would return at once (always, for host fields).
    bool nextReady() const;
    // Ring: produces the next frame (not pipelined) or waits for it; its
    // production times. Host: nothing yet (the fields advance in publishNext).
    const ProducedFrame& waitNext();
    // Makes the next frame current: publishes the ring slot, or advances the
    // host fields by one frame.
    void publishNext();

    // Host fields whose frames are independent (SceneFields::framesAreIndependent):
    // makes frame `frame` current directly, for a process that renders every
    // K-th frame of a run.
    void seekFrame(int frame);

    // What produced the current frame, and its fields (ring slot or host memory).
    const ProducedFrame& current() const;
    ConstFieldViews currentViews() const;

private:
    sim::SceneFields& fields_;
    ExportNeeds exports_;
    int hostFrame_ = 0;                 // the frame the host fields hold
    std::unique_ptr<LiveFrames> live_;  // a fluid solver's frames, through the ring
    ProducedFrame host_;                // otherwise: what produced the host fields
    std::unique_ptr<render::FrameRenderer> renderer_;
};

}  // namespace eikon::app
