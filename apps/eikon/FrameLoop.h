// The frame loop of `eikon run`: fields → renderer → frame image, report
// line and export. Its fields come from the frame source it shares with the
// viewer (apps/common/FrameSource.h): host memory, or for a scene with a
// fluid solver the zero-copy field ring, simulated one frame ahead of the
// renderer when pipelined.
#pragma once

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

// How the ranks of an MPI job share a run (apps/eikon/Ranks.h): not at all
// (one process); each frame's light pass (every rank simulates the same
// fields and traces its share of the photons; rank 0 draws and writes); or
// whole frames (rank r renders frames r, r + K, …; FrameShareLoop.h).
enum class Distribution { None, Photons, Frames };
const char* distributionName(Distribution distribution);

struct LoopOptions {
    bool pipelined = true;  // simulate frame k+1 while frame k renders
    Distribution distribution = Distribution::None;
    std::filesystem::path outputRoot;  // the folder ranks sharing frames write into (rank 0 opens it)
};

// Wall times of one turn of the loop: the whole frame, the renderer's
// stages, and the simulation of the next frame (which runs during the
// render when pipelined); hidden = simulate + render − frame.
struct LoopTiming {
    double frameMs = 0.0;
    double renderMs = 0.0;
    double produceNextMs = 0.0;
};

// The renderer's stages' wall time together.
double renderMilliseconds(const render::FrameResult& result);

// One line of report.jsonl: simulated time, stages (ran, ms) including the
// simulation's, host and GPU bytes copied, photon figures and energy
// balance, and how the ranks of an MPI job shared the run.
std::string frameReportJson(int frame, const ProducedFrame& produced, bool simulated,
                            const render::FrameResult& result, const LoopTiming& timing, bool pipelined,
                            Distribution distribution = Distribution::None);

// Opens the output folder; called once frame 0 is rendered, so that a scene
// whose GPU resources do not fit is refused before anything is written.
using OpenOutput = std::function<io::OutputFolder&()>;

// Renders `frames` frames, advancing the simulation (if any) between them;
// frames the scene's `export` section selects also go to DIR/vtk/ and DIR/vdb/.
void runFrames(const Scene& scene, sim::SceneFields& fields, int frames, const OpenOutput& openOutput,
               ProgressBar& progress, const LoopOptions& options = {});

}  // namespace eikon::app
