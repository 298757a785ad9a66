// The frame loop of `eikon run`: fields → renderer → frame image, report
// line and export. Its fields come from the frame source it shares with the
// viewer (apps/common/FrameSource.h): host memory, or for a scene with a
// fluid solver the zero-copy field ring, simulated one frame ahead of the
// renderer when pipelined.
#pragma once

#include "apps/common/FrameReport.h"
#include "apps/common/LiveFrames.h"
#include "apps/eikon/ProgressBar.h"
#include "io/files/OutputFolder.h"
#include "bridge/scene/Scene.h"
#include "render/graph/FrameRenderer.h"
#include "sim/SceneFields.h"

#include <filesystem>
#include <functional>
#include <string>

namespace eikon::app {

struct LoopOptions {
    bool pipelined = true;  // simulate frame k+1 while frame k renders
    Distribution distribution = Distribution::None;
    std::filesystem::path outputRoot;  // the folder ranks sharing frames write into (rank 0 opens it)
};

// Opens the output folder; called once frame 0 is rendered, so that a scene
// whose GPU resources do not fit is refused before anything is written.
using OpenOutput = std::function<io::OutputFolder&()>;

// Renders `frames` frames, advancing the simulation (if any) between them;
// frames the scene's `export` section selects also go to DIR/vtk/ and DIR/vdb/.
// A followed volume (SceneFields::followedVolume) is awaited after each
// frame's outputs, and the run ends early when following ends; its report
// names each frame's step and the steps skipped (FollowReport.h).
void runFrames(const Scene& scene, sim::SceneFields& fields, int frames, const OpenOutput& openOutput,
               ProgressBar& progress, const LoopOptions& options = {});

}  // namespace eikon::app
