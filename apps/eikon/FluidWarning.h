// Says on stderr, once a run, when a frame of the fluid solver moved its
// fastest flow further in a substep than advection can follow
// (sim/fluid/FrameReport.h, describeFastFlow): its velocities mean little.
// The report's fluid.fast_flow_warning carries the same words every frame.
#pragma once

#include "apps/common/LiveFrames.h"

namespace eikon::app {

class FluidWarning {
public:
    void check(int frame, const ProducedFrame& produced);

private:
    bool warned_ = false;
};

}  // namespace eikon::app
