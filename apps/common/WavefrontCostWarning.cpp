#include "apps/common/WavefrontCostWarning.h"

#include "render/graph/FrameRenderer.h"
#include "render/stages/WavefrontStage.h"

#include <cstdio>

#include <iostream>

namespace eikon::app {

namespace {

constexpr std::uint64_t kLargeStart = 1000000;
// The light pass's time per start patch on the default scene, on 2 CPU cores
// with llvmpipe: 10.6 s for 1.05 million (grid_cells 512), 34.8 s for 4.19
// million (1024), refinement included (docs/benchmarks-wavefront.md).
constexpr double kSecondsPerStartPatch = 8e-6;

}  // namespace

std::string describeWavefrontStart(std::uint64_t startPatches) {
    if (startPatches < kLargeStart) return {};
    char text[400];
    std::snprintf(text, sizeof text,
                  "the wavefronts start with %.3g million patches a frame (tracer.wavefront.grid_cells), about "
                  "%.0f s a frame on 2 CPU cores with llvmpipe at 8 µs a patch (docs/benchmarks-wavefront.md); "
                  "fewer grid_cells cost less, and the refinement still splits where the light needs it",
                  static_cast<double>(startPatches) / 1e6, static_cast<double>(startPatches) * kSecondsPerStartPatch);
    return text;
}

void warnWavefrontStart(const Scene& scene, bool scatters) {
    if (scene.render.method != RenderDesc::Method::Eikonal ||
        scene.tracer.estimator != TracerDesc::Estimator::Wavefront || !render::tracesLight(scene, scatters))
        return;
    const std::string warning = describeWavefrontStart(render::wavefrontStartPatches(scene));
    if (!warning.empty()) std::cerr << "eikon: warning: " << warning << "\n";
}

}  // namespace eikon::app
