// accuracy.png and accuracy.svg: error against run time, log–log, one panel
// per case and one curve per integrator and step policy (the sweeps over
// grid, smoothing, octree tolerances and photon count as their own marked
// curves, and image space over its size as one more), drawn by PLplot
// (verify/plot/LogLogFigure.h).
#pragma once

#include "verify/accuracy/AccuracyRun.h"

#include <filesystem>
#include <vector>

namespace eikon::accuracy {

void writeErrorPlot(const std::filesystem::path& file, const std::vector<RunRecord>& records);

}  // namespace eikon::accuracy
