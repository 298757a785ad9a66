#include "apps/eikon-view/SimulationPacer.h"

namespace eikon::view {

bool SimulationPacer::advances(bool cameraMoving) const {
    if (!cameraMoving || target_ <= 0.0) return true;
    if (drawingAdvance_) return false;
    if (heldMs_ >= kLongestHoldMs) return true;
    return (heldMs_ + advanceMs_) / static_cast<double>(held_ + 2) <= target_;
}

void SimulationPacer::frameDone(bool advanced, bool cameraMoving, double frameMs) {
    if (advanced) {
        drawingAdvance_ = true;
        simulatedMs_ = frameMs;
        simulatedMoving_ = cameraMoving;
        heldMs_ = 0.0;
        held_ = 0;
    } else if (drawingAdvance_) {
        drawingAdvance_ = false;
        if (simulatedMoving_ && cameraMoving) advanceMs_ = simulatedMs_ + frameMs;
    } else {
        heldMs_ += frameMs;
        ++held_;
    }
}

}  // namespace eikon::view
