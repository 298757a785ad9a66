// Says on stderr, once a run, when a frame's estimated noise or
// discretisation error (render/stages/ErrorEstimateStage.h) of any output
// exceeds render.warn_error, with what to change.
#pragma once

#include "render/graph/FrameRenderer.h"

namespace eikon::app {

class ErrorWarning {
public:
    explicit ErrorWarning(double threshold) : threshold_(threshold) {}
    void check(int frame, const render::FrameResult& result);

private:
    double threshold_;
    bool warned_ = false;
};

}  // namespace eikon::app
