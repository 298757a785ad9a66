// What a wavefront light pass costs where its settings make it long. Its
// start is known before it runs: every emitter face's grid_cells² cells of
// two patches in every wavefront (render/stages/WavefrontStage.h). From a
// million start patches on, `eikon run` says so on stderr before the first
// frame, and each frame's report carries the same words beside its
// start_patches. What refinement adds depends on the scene; its measured
// costs are in docs/benchmarks-wavefront.md.
#pragma once

#include "bridge/scene/Scene.h"

#include <cstdint>
#include <string>

namespace eikon::app {

// The warning for this many start patches; empty below a million.
std::string describeWavefrontStart(std::uint64_t startPatches);

// On stderr, where the scene traces wavefronts whose start is that large
// (`scatters`: some voxel of its fields scatters light).
void warnWavefrontStart(const Scene& scene, bool scatters);

}  // namespace eikon::app
