// While the camera moves the viewer puts the camera first: a moving scene
// (a fluid solver, a deformer, water) advances on a frame only when the
// mean frame time since its last advance, this advance included, stays
// within the interactive target, and at least once every kLongestHoldMs of
// wall time. Frames between advances redraw the same fields from the new
// camera (the view pass alone), so orbiting stays fluid while the
// simulation goes on at a slower pace. At rest, or with no target, it
// advances every frame.
//
// An advance costs two frames: the one that simulates, and the next, which
// draws the new fields (the field stages: upload, prepare, photons…). The
// pacer measures the two together and never advances on the second.
// The policy is plain arithmetic on frame times, tested without a window.
#pragma once

namespace eikon::view {

// The longest the simulation is held while the camera moves.
constexpr double kLongestHoldMs = 500.0;

class SimulationPacer {
public:
    // `targetFrameMs`: the mean frame time to keep while the camera moves; 0: never hold.
    explicit SimulationPacer(double targetFrameMs) : target_(targetFrameMs) {}

    // Before a frame: whether a moving scene advances on it, given whether
    // the camera is moving (moved within the refine delay, ViewPreview::cameraMoving).
    bool advances(bool cameraMoving) const;
    // After the frame: whether it advanced, whether the camera was moving,
    // and its wall time.
    void frameDone(bool advanced, bool cameraMoving, double frameMs);

private:
    double target_;
    double advanceMs_ = 0.0;  // the last advance's two frames while moving (0: not measured yet)
    bool drawingAdvance_ = false;  // the last frame advanced: this one draws its fields
    double simulatedMs_ = 0.0;     // that frame's time
    bool simulatedMoving_ = false; // and whether the camera moved in it
    double heldMs_ = 0.0;          // frames drawn since, and their time
    int held_ = 0;
};

}  // namespace eikon::view
