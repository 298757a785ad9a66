// One frame's report (a line of `eikon run`'s report.jsonl, and the
// library's Renderer::report): simulated time, stages (ran, ms), bytes
// copied, photon figures and energy balance, the lattice, the error
// estimate; the units are in the keys' names (docs/architecture.md).
#pragma once

#include "apps/common/LiveFrames.h"
#include "render/graph/FrameRenderer.h"

#include <string>

namespace eikon::app {

// How the ranks of an MPI job share a run (apps/eikon/Ranks.h): not at all
// (one process); each frame's light pass (every rank simulates the same
// fields and traces its share of the photons; rank 0 draws and writes); or
// whole frames (rank r renders frames r, r + K, …; FrameShareLoop.h).
enum class Distribution { None, Photons, Frames };
const char* distributionName(Distribution distribution);

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
// balance, and how the `ranks` processes of an MPI job shared the run.
std::string frameReportJson(int frame, const ProducedFrame& produced, bool simulated,
                            const render::FrameResult& result, const LoopTiming& timing, bool pipelined,
                            Distribution distribution = Distribution::None, int ranks = 1);

}  // namespace eikon::app
