// `--distribute frames`: rank r of K renders frames r, r + K, … of a scene
// whose frames do not depend on each other (SceneFields::framesAreIndependent),
// each made directly (FrameSource::seekFrame). Rank 0 renders frame 0 and
// opens the output folder before any rank writes (a scene that does not fit
// is refused with nothing written); every rank writes its frames' files;
// rank 0 gathers nothing but the report lines and frame times, and writes
// report.jsonl and the series indexes once all frames exist.
#pragma once

#include "apps/eikon/ProgressBar.h"
#include "bridge/scene/Scene.h"
#include "io/files/OutputFolder.h"
#include "sim/SceneFields.h"

#include <filesystem>
#include <functional>

namespace eikon::app {

void renderFrameShare(const Scene& scene, sim::SceneFields& fields, int frames,
                      const std::function<io::OutputFolder&()>& openOutput, ProgressBar& progress,
                      const std::filesystem::path& outputRoot);

}  // namespace eikon::app
