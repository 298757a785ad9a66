#include "apps/eikon/LatticeWarning.h"

#include <cstdio>

#include <iostream>

namespace eikon::app {

namespace {

std::string threeDigits(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", value);
    return text;
}

}  // namespace

std::string describeDepthLimit(const render::LatticeDepth& depth) {
    if (depth.thickVoxels == 0) return {};
    return std::to_string(depth.thickVoxels) + " voxels of albedo near 1 are too thick for the multiple-scattering "
           "lattice: optical depth up to " + threeDigits(depth.deepest) + " across a voxel, beyond its limit of " +
           threeDigits(depth.limit) + " (float precision of its transfer at albedo 1); their light is lost or "
           "gained by rounding, so the lattice is not converged: use a finer grid (grid.resolution) or a lower "
           "extinction there";
}

void LatticeWarning::check(int frame, const render::FrameResult& result) {
    if (warned_ || !result.lattice) return;
    const std::string description = describeDepthLimit(result.lattice->depth);
    if (description.empty()) return;
    std::cerr << "eikon: warning: frame " << frame << ": " << description << "; later frames are not reported here\n";
    warned_ = true;
}

}  // namespace eikon::app
