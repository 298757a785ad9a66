// accuracy.png: error against run time, log–log, one panel per case and one
// curve per integrator and step policy (the sweeps over grid, smoothing,
// octree tolerances and photon count as their own marked curves). Drawn by a
// small rasterizer (lines, markers, stb_easy_font text) and written as PNG
// through io/image/ImageIo: no plotting library renders headless here.
#pragma once

#include "verify/accuracy/AccuracyRun.h"

#include <filesystem>
#include <vector>

namespace eikon::accuracy {

void writeErrorPlot(const std::filesystem::path& file, const std::vector<RunRecord>& records);

}  // namespace eikon::accuracy
