#include "apps/eikon/WarmShadersCommand.h"

#include "apps/common/FrameSource.h"
#include "apps/eikon/FrameExport.h"
#include "gl/GlContext.h"
#include "io/scene/SceneParser.h"
#include "render/graph/MemoryEstimate.h"
#include "sim/SceneFields.h"

#include <chrono>
#include <cstdio>
#include <memory>

namespace eikon::app {

namespace {

// One scene's first frame through the run's own frame source (the same
// renderer options, so the same program variants), and, for a scene that
// changes over time, the production of its second frame: a solver's
// programs are dispatched then.
void renderFirstFrame(const std::string& scenePath, const gl::GlContext& context) {
    const Scene scene = loadSceneFile(scenePath, {});
    render::requireMemoryFits(scene);
    sim::SceneFields fields(scene);
    fields.placeFluidSolver(!context.info().rendersOnCpu());
    fields.placeWater(!context.info().rendersOnCpu());
    FrameSource source(scene, fields, rendererOptionsFor(scene), /*pipelined=*/false, ExportNeeds());
    const bool more = fields.changesOverTime();
    if (more) source.beginNext();
    source.render();
    if (more) source.waitNext();
}

}  // namespace

void addWarmShadersCommand(CLI::App& app, WarmShadersOptions& options) {
    CLI::App* warm = app.add_subcommand(
        "warm-shaders",
        "Compile every shader the scenes use into the driver's shader cache (renders each scene's first frame, "
        "writes no output)");
    warm->add_option("scenes", options.scenePaths, "Scene files (JSON)")->required();
}

int warmShadersCommand(const WarmShadersOptions& options) {
    const auto context = gl::createHeadlessContext();
    for (const std::string& scenePath : options.scenePaths) {
        const auto start = std::chrono::steady_clock::now();
        renderFirstFrame(scenePath, *context);
        const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
        std::fprintf(stderr, "eikon warm-shaders: %s: first frame rendered in %.1f s on %s\n", scenePath.c_str(),
                     seconds.count(), context->info().renderer.c_str());
    }
    return 0;
}

}  // namespace eikon::app
