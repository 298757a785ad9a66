// Says on stderr, once a run, when a frame's multiple-scattering lattice
// holds voxels beyond its depth limit (render/stages/LatticeScattering.h):
// their light is lost or gained by rounding, the lattice is not converged,
// and the report's multiple_scattering.depth_limit carries the same words;
// and, once a run, when its scattering voxels are coarser than its
// validated resolution (LatticeResolution), the words of the report's
// multiple_scattering.voxel_resolution and error_estimate.multiple_scattering.
#pragma once

#include "render/graph/FrameRenderer.h"

#include <string>

namespace eikon::app {

// What is wrong and what to change; empty where no voxel is beyond the limit.
std::string describeDepthLimit(const render::LatticeDepth& depth);
// The same where voxels are coarser than the validated resolution.
std::string describeResolution(const render::LatticeResolution& resolution);

class LatticeWarning {
public:
    void check(int frame, const render::FrameResult& result);

private:
    bool warned_ = false, warnedResolution_ = false;
};

}  // namespace eikon::app
