// A frame's stage times as the preview policy (ViewPreview) reads them, for
// eikon-view and eikon::View alike.
#pragma once

#include "render/graph/FrameRenderer.h"

namespace eikon::view {

// The time of stage `name` in `frame` (ms), 0 where it did not run.
inline double stageMilliseconds(const render::FrameResult& frame, const char* name) {
    for (const auto& stage : frame.stages)
        if (stage.name == name && stage.ran) return stage.milliseconds;
    return 0.0;
}

// The stage that draws a frame's picture: a diagnostic's instrument, or the view.
inline const char* pictureStage(bool diagnostic) { return diagnostic ? "diagnostic" : "view"; }

}  // namespace eikon::view
