// The viewer's Dear ImGui panel: settings the user edits, the stage timings
// and error figures of the last frame, and buttons. Edits of the tracer,
// materials or solver are collected into a scene and applied on request
// (they rebuild the session); photons and exposure apply at once.
#pragma once

#include "bridge/scene/Scene.h"
#include "render/graph/FrameRenderer.h"

#include <string>

namespace eikon::view {

struct PanelRequests {
    bool apply = false;       // rebuild the session from `edited`
    bool reset = false;       // restart the simulation from its initial state
    bool step = false;        // advance one frame while paused
    bool screenshot = false;
};

struct ViewerStatus {
    std::string sceneName;
    std::string message;      // last error (e.g. a reload that failed) or note
    bool simulated = false;
    bool paused = false;
    bool pipelined = false;
    double simulatedTime = 0.0;
    std::string solverDevice;  // where the fluid solver runs: "cpu", "gpu", or "" without one
    std::string waterDevice;   // where a water body's frames are made: "cpu", "gpu", or "" without one
    double framesPerSecond = 0.0;
    long long photonsInUse = 0;
    bool imageSpacePreview = false;  // on screen: the image-space preview of an eikonal scene
    bool simulationHeld = false;     // this frame redrew the camera and held the simulation (SimulationPacer.h)
};

class ControlPanel {
public:
    explicit ControlPanel(const Scene& scene) : edited_(scene) {}

    // Draws the panel for this frame; `paused`, `pipelined`, `exposure` and
    // `photons` are edited in place.
    PanelRequests draw(const render::FrameResult& last, ViewerStatus& status, bool& paused, bool& pipelined,
                       double& exposureEv, long long& photons);

    const Scene& edited() const { return edited_; }
    void reset(const Scene& scene) { edited_ = scene; }

private:
    Scene edited_;
};

}  // namespace eikon::view
