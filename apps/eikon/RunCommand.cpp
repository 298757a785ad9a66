#include "apps/eikon/RunCommand.h"

#include "apps/eikon/FrameLoop.h"
#include "bridge/core/Error.h"
#include "apps/eikon/ProgressBar.h"
#include "io/files/OutputFolder.h"
#include "io/scene/ExportParser.h"
#include "io/scene/SceneParser.h"
#include "render/gl/GlContext.h"
#include "render/gl/GpuMemory.h"
#include "render/stages/PhotonStage.h"
#include "sim/SceneFields.h"

#include <filesystem>
#include <optional>

namespace eikon::app {

void addRunCommand(CLI::App& app, RunOptions& options) {
    CLI::App* run = app.add_subcommand("run", "Render a scene headless: DIR/frames/frame_NNNNN.png and DIR/report.jsonl");
    run->add_option("scene", options.scenePath, "Scene file (JSON, see docs/scene-format.md)")->required();
    run->add_option("--out", options.outDir, "Output folder (default: out/<scene name>)");
    run->add_option("--frames", options.frames, "Number of frames to render")->check(CLI::Range(1, 1000000));
    run->add_option("--set", options.overrides, "Override a scene value, e.g. --set render.photons=100000")
        ->type_name("KEY.PATH=VALUE");
    run->add_flag("--quiet", options.quiet, "No progress bar");
    run->add_flag("--force", options.force, "Clear the output folder if it holds an earlier run");
    run->add_option("--pipelining", options.pipelining,
                    "Simulate frame k+1 while frame k renders: on, off, or auto (on unless OpenGL renders on the CPU "
                    "cores the simulation uses, as llvmpipe does)")
        ->check(CLI::IsMember({"auto", "on", "off"}));
    run->add_flag("--vtk", options.vtk,
                  "Export every frame's fields as DIR/vtk/fields_NNNNN.vti with a .pvd and .series for ParaView, "
                  "with the default field set, whatever the scene's export.vtk says");
}

int runCommand(const RunOptions& options) {
    // Everything the user supplied is checked before anything is written.
    Scene scene = loadSceneFile(options.scenePath, options.overrides);
    if (options.vtk) {  // the default field set, whatever the scene says
        scene.exports.vtk = VtkExportDesc{};
        scene.exports.vtk.enabled = true;
    }
    if (scene.volume) requireVolumeFrames(*scene.volume, options.frames);
    sim::SceneFields fields(scene);
    render::requireEstimatorFits(scene, fields.fields().hasScattering() || fields.scatteringChangesOverTime());
    const std::filesystem::path outDir =
        options.outDir.empty() ? std::filesystem::path("out") / std::filesystem::path(options.scenePath).stem()
                               : std::filesystem::path(options.outDir);
    io::OutputFolder::requireUsable(outDir, options.force);
    auto context = gl::createHeadlessContext();  // before the folder: a machine without GL leaves nothing behind
    ProgressBar progress(options.frames, options.quiet);
    const bool pipelined =
        options.pipelining == "on" || (options.pipelining == "auto" && !context->info().rendersOnCpu());
    std::optional<io::OutputFolder> output;
    try {
        runFrames(scene, fields, options.frames, [&]() -> io::OutputFolder& { return output.emplace(outDir, options.force); },
                  progress, {pipelined});
    } catch (const gl::GpuMemoryError& error) {  // a size the scene asked for, too large for this machine
        throw InputError(scene.sourcePath + ": " + error.what());
    }
    return 0;
}

}  // namespace eikon::app
