// The frame loop shared by `eikon run` and the viewer: fields → renderer →
// frame image and report line.
#pragma once

#include "apps/eikon/ProgressBar.h"
#include "bridge/grid/FieldSet.h"
#include "bridge/io/OutputFolder.h"
#include "bridge/scene/Scene.h"
#include "render/graph/FrameRenderer.h"

#include <string>

namespace eikon::app {

// One line of report.jsonl: stages (ran, ms), host bytes, energy balance.
std::string frameReportJson(int frame, const render::FrameResult& result);

void runFrames(const Scene& scene, const FieldSet& fields, int frames, io::OutputFolder& output, ProgressBar& progress);

}  // namespace eikon::app
