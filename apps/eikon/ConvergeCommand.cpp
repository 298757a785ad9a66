#include "apps/eikon/ConvergeCommand.h"

#include "bridge/core/Error.h"
#include "bridge/core/NumberFormat.h"
#include "io/files/AtomicFile.h"
#include "io/files/OutputFolder.h"
#include "io/scene/SceneParser.h"
#include "gl/GlContext.h"
#include "gl/GpuMemory.h"
#include "verify/converge/ConvergeReport.h"
#include "verify/converge/ConvergeStudy.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace eikon::app {

namespace {

// The outputs asked for, each one the scene has; all it has when none is named.
converge::Outputs requestedOutputs(const std::string& list, const converge::Outputs& available) {
    if (list.empty()) return available;
    converge::Outputs requested;
    std::stringstream items(list);
    for (std::string item; std::getline(items, item, ',');) {
        bool* flag = item == "receivers" ? &requested.receivers : item == "image" ? &requested.image
                                                               : item == "fluence" ? &requested.fluence : nullptr;
        const bool has = item == "receivers" ? available.receivers : item == "image" ? available.image
                                                                  : item == "fluence" && available.fluence;
        if (!flag) throw InputError("--outputs", "receivers, image or fluence, comma-separated", "\"" + item + "\"");
        if (!has)
            throw InputError("--outputs", "an output the scene has (receivers where it has any, fluence where it "
                                          "scatters or stores it)", "\"" + item + "\"");
        *flag = true;
    }
    return requested;
}

// The scene file with a rung's settings written into it, as the scene
// loader makes it: every documented range applies to a reference too.
Scene loadedScene(const nlohmann::json& document, const ConvergeOptions& options, const converge::Rung& rung) {
    nlohmann::json refined = document;
    for (const std::string& assignment : rung.overrides) applyOverride(refined, assignment);
    try {
        return parseScene(refined, options.scenePath);
    } catch (const InputError& error) {
        throw InputError((options.reference.empty() ? "the default --reference: its " : "--reference: the reference's ") +
                         rung.setting + " is refused as the scene file would be: " + error.what());
    }
}

std::string commandLine(const ConvergeOptions& options) {
    std::string command = "eikon converge " + options.scenePath + " --budget-s " + formatNumber(options.budgetSeconds);
    if (options.frame > 0) command += " --frame " + std::to_string(options.frame);
    if (!options.outputs.empty()) command += " --outputs " + options.outputs;
    if (!options.reference.empty()) command += " --reference " + options.reference;
    for (const std::string& value : options.overrides) command += " --set " + value;
    return command;
}

}  // namespace

void addConvergeCommand(CLI::App& app, ConvergeOptions& options) {
    CLI::App* converge = app.add_subcommand(
        "converge", "Error against run time for your own scene: a self-convergence study over its knobs "
                    "(photons or wavefront refinement, step, grid) within a time budget");
    converge->add_option("scene", options.scenePath, "Scene file (JSON, see docs/scene-format.md)")->required();
    converge->add_option("--out", options.outDir, "Output folder for converge.csv, converge.png/.svg, converge.md")
        ->required();
    converge->add_option("--budget-s", options.budgetSeconds, "Wall-time budget in seconds (default 300)");
    converge->add_option("--frame", options.frame, "Frame of the scene to study (default 0)")
        ->check(CLI::Range(0, 1000000));
    converge->add_option("--outputs", options.outputs,
                         "Outputs to compare, comma-separated: receivers, image, fluence (default: all the scene has)");
    const converge::Refinement& most = converge::kFinestReference;
    converge->add_option("--reference", options.reference,
                         "How much finer the reference is, e.g. photons=16,step=4,grid=1.5, each from 1 to " +
                             formatNumber(most.photons) + ", " + formatNumber(most.step) + " and " +
                             formatNumber(most.grid) + " (default: as fits the budget)");
    converge->add_option("--set", options.overrides, "Override a scene value, e.g. --set render.photons=100000")
        ->type_name("KEY.PATH=VALUE");
    converge->add_flag("--force", options.force, "Clear the output folder if it holds an earlier study");
}

int convergeCommand(const ConvergeOptions& options) {
    // Every input is checked before anything is written.
    if (!(options.budgetSeconds > 0.0) || !std::isfinite(options.budgetSeconds))
        throw InputError("--budget-s", "a number of seconds > 0", formatNumber(options.budgetSeconds));
    std::optional<converge::Refinement> reference;
    if (!options.reference.empty()) reference = converge::parseReference(options.reference, "--reference");
    const nlohmann::json document = loadSceneDocument(options.scenePath, options.overrides);
    const Scene scene = parseScene(document, options.scenePath);
    const auto context = gl::createHeadlessContext();
    const converge::Outputs outputs = requestedOutputs(options.outputs, converge::outputsOf(scene));
    const std::filesystem::path out(options.outDir);
    io::OutputFolder::requireUsable(out, options.force);

    converge::StudyOptions study{options.budgetSeconds, options.frame, outputs, reference, [](const converge::Measured& m) {
        std::printf("%-10s %-70s %8.3f s  worst error %.3g\n", m.rung.knob.c_str(), m.rung.setting.c_str(), m.seconds,
                    m.worst());
        std::fflush(stdout);
    }, [&](const converge::Rung& rung) { return loadedScene(document, options, rung); }};
    converge::Study result;
    try {
        result = converge::runStudy(scene, study);
    } catch (const gl::GpuMemoryError& error) {  // a size the scene or --reference asked for, too large for this machine
        throw InputError(scene.sourcePath + ": " + error.what());
    }
    io::OutputFolder folder(out, options.force, /*withFrames=*/false);
    io::writeFileAtomically(out / "converge.csv", converge::csvText(result));
    converge::writePlot(result, out);
    io::writeFileAtomically(out / "converge.md",
                            converge::markdownText(result, commandLine(options), context->info().renderer));
    std::printf("%zu settings and the reference in %.0f s: %s\n", result.rungs.size(), result.wallSeconds,
                out.string().c_str());
    return 0;
}

}  // namespace eikon::app
