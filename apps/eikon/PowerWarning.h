// Says on stderr, once a run, when the lights emitted other than the power
// they state (emission error above 1e-3: PhotonStats::emissionError), when
// a frame's photons do not account for their power (balance error above
// 1e-3), or when photons stopped before
// their light was spent lose more than 0.1% of it net of the roulette's
// gain (tracer.max_steps, or a single step past llvmpipe's loop cap): the
// figures are then not what the scene would give.
#pragma once

#include "render/graph/FrameRenderer.h"

namespace eikon::app {

class PowerWarning {
public:
    void check(int frame, const render::FrameResult& result);

private:
    bool warned_ = false;
};

}  // namespace eikon::app
