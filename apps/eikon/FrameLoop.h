// The frame loop shared by `eikon run` and the viewer: fields → renderer →
// frame image and report line.
#pragma once

#include "apps/eikon/ProgressBar.h"
#include "bridge/io/OutputFolder.h"
#include "bridge/scene/Scene.h"
#include "render/graph/FrameRenderer.h"
#include "sim/SceneFields.h"

#include <string>

namespace eikon::app {

// One line of report.jsonl: simulated time and solver phases, stages (ran,
// ms), host bytes, photon figures and energy balance.
std::string frameReportJson(int frame, const sim::SceneFields& fields, const render::FrameResult& result);

// Renders `frames` frames, advancing the simulation (if any) between them;
// frames the scene's `export` section selects also go to DIR/vtk/ and DIR/vdb/.
void runFrames(const Scene& scene, sim::SceneFields& fields, int frames, io::OutputFolder& output,
               ProgressBar& progress);

}  // namespace eikon::app
