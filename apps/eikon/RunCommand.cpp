#include "apps/eikon/RunCommand.h"

#include "apps/common/FollowedVolume.h"
#include "apps/eikon/FrameLoop.h"
#include "apps/eikon/Ranks.h"
#include "apps/eikon/RunAgreement.h"
#include "bridge/core/Error.h"
#include "apps/eikon/ProgressBar.h"
#include "io/files/OutputFolder.h"
#include "io/scene/SceneFingerprint.h"
#include "io/scene/SceneParser.h"
#include "io/vdb/VolumePlacement.h"
#include "gl/GlContext.h"
#include "gl/GpuMemory.h"
#include "render/graph/MemoryEstimate.h"
#include "render/stages/PhotonStage.h"
#include "sim/SceneFields.h"
#include "sim/volume/VolumeSequence.h"

#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>

namespace eikon::app {

void addRunCommand(CLI::App& app, RunOptions& options) {
    CLI::App* run = app.add_subcommand("run", "Render a scene headless: DIR/frames/frame_NNNNN.png and DIR/report.jsonl");
    run->add_option("scene", options.scenePath, "Scene file (JSON, see docs/scene-format.md)")->required();
    run->add_option("--out", options.outDir, "Output folder (default: out/<scene name>)");
    run->add_option("--frames", options.frames, "Number of frames to render (with --follow: at most)")
        ->check(CLI::Range(1, 1000000))
        ->each([&options](const std::string&) { options.framesGiven = true; });
    run->add_option("--set", options.overrides, "Override a scene value, e.g. --set render.photons=100000")
        ->type_name("KEY.PATH=VALUE");
    run->add_flag("--quiet", options.quiet, "No progress bar");
    run->add_flag("--force", options.force, "Clear the output folder if it holds an earlier run");
    run->add_option("--pipelining", options.pipelining,
                    "Simulate frame k+1 while frame k renders: on, off, or auto (on unless OpenGL renders on the CPU "
                    "cores the simulation uses, as llvmpipe does)")
        ->check(CLI::IsMember({"auto", "on", "off"}));
    run->add_option("--distribute", options.distribute,
                    "Under mpirun: how the ranks share the run. photons: each traces its share of every frame's "
                    "photons and rank 0 writes the frame (bit-identical to one process); frames: rank r renders "
                    "frames r, r+K, ... of a scene whose frames are independent (no fluid solver, no moving "
                    "objects); auto: frames where they are independent and there are several, else photons")
        ->check(CLI::IsMember({"auto", "photons", "frames"}));
    CLI::Option* follow = run->add_flag("--follow", options.follow,
                  "Follow the scene's volume (a .pvd or .series time series, an OpenFOAM case) as a simulation "
                  "writes it: render each new step once it is complete, skip a damaged one with a warning");
    run->add_option("--follow-poll-ms", options.followPollMs,
                    "With --follow: milliseconds between looks at the series (a step is complete once its files "
                    "are unchanged between two looks and it reads)")
        ->check(CLI::Range(1.0, 600000.0))
        ->needs(follow);
    run->add_option("--follow-timeout", options.followTimeoutS,
                    "With --follow: seconds without a new complete step after which following ends")
        ->check(CLI::Range(0.001, 1e7))
        ->needs(follow);
    run->add_option("--follow-stop", options.followStop,
                    "With --follow: following ends once this file exists and the steps listed are read")
        ->type_name("FILE")
        ->needs(follow);
    run->add_flag("--vtk", options.vtk,
                  "Export the fields as DIR/vtk/fields_NNNNN.vti with a .pvd and .series for ParaView: turns "
                  "export.vtk on, with the settings the scene and --set give it (every frame and field by default)");
}

namespace {

// What --distribute asks for, on the ranks there are: InputError where
// `frames` is asked of a scene whose frames depend on each other.
Distribution chooseDistribution(const RunOptions& options, const Scene& scene, const sim::SceneFields& fields,
                                const Ranks& ranks) {
    if (!ranks.distributed()) return Distribution::None;
    const bool independent = fields.framesAreIndependent();
    if (options.distribute == "frames" && !independent)
        throw InputError(scene.sourcePath + ": --distribute",
                         "photons for a scene whose frames depend on each other (a fluid solver, moving meshes or "
                         "water)",
                         "frames");
    if (options.distribute == "photons") return Distribution::Photons;
    if (options.distribute == "frames") return Distribution::Frames;
    return independent && options.frames > 1 ? Distribution::Frames : Distribution::Photons;
}

// The user's --set assignments, then --vtk's: export.vtk turned on, its
// other settings as the scene file and --set give them.
std::vector<std::string> overridesOf(const RunOptions& options) {
    std::vector<std::string> overrides = options.overrides;
    if (options.vtk) overrides.push_back("export.vtk.enabled=true");
    return overrides;
}

}  // namespace

int runCommand(const RunOptions& options) {
    Ranks& ranks = Ranks::world();
    // The context outlives the fields: a solver on the GPU holds GL objects.
    std::unique_ptr<gl::GlContext> context;
    Scene scene;
    std::unique_ptr<sim::SceneFields> fields;
    std::filesystem::path outDir;
    Distribution distribution = Distribution::None;
    std::string fingerprint;
    // Everything the user supplied is checked before anything is written,
    // by every rank alike, and the ranks agree on it (Ranks::checkInputsTogether).
    Ranks::Agreement agreement;
    const int frames = options.follow && !options.framesGiven ? std::numeric_limits<int>::max() : options.frames;
    ranks.checkInputsTogether([&] {
        const nlohmann::json document = loadSceneDocument(options.scenePath, overridesOf(options));
        scene = parseScene(document, options.scenePath);
        fingerprint = sceneFingerprint(document);
        if (options.follow) {
            if (ranks.distributed())
                throw InputError(scene.sourcePath + ": --follow", "one process (steps come one at a time)",
                                 std::to_string(ranks.size()) + " MPI ranks");
            followVolume(scene, {options.followPollMs / 1000.0, options.followTimeoutS, options.followStop});
        } else if (scene.volume) {
            sim::checkVolumeFrames(*scene.volume, scene.grid.spec(), options.frames, scene.sourcePath);
        }
        render::requireMemoryFits(scene);  // before the fields, the GL context or anything the scene sizes
        fields = std::make_unique<sim::SceneFields>(scene);
        if (scene.volume && ranks.first()) {  // once its first file has loaded: it is readable
            const std::string outside = io::describeVolumeOutsideGrid(*scene.volume, scene.grid.spec());
            if (!outside.empty()) std::cerr << "eikon: warning: " << scene.sourcePath << ": " << outside << "\n";
        }
        distribution = chooseDistribution(options, scene, *fields, ranks);
        outDir = options.outDir.empty()
                     ? std::filesystem::path("out") / std::filesystem::path(options.scenePath).stem()
                     : std::filesystem::path(options.outDir);
        if (ranks.distributed()) agreement = runAgreement(options, outDir, document, scene);
        if (ranks.first()) io::OutputFolder::requireUsable(outDir, options.force);
        // Before the folder: a machine without GL leaves nothing behind. A
        // rank takes the GPU of its local rank where a machine has several.
        context = gl::createHeadlessContext(static_cast<unsigned>(ranks.localRank()));
        fields->placeFluidSolver(!context->info().rendersOnCpu());
        fields->placeWater(!context->info().rendersOnCpu());
    }, agreement);
    const int ownFrames =
        distribution == Distribution::Frames ? (options.frames + ranks.size() - 1) / ranks.size() : options.frames;
    // Following, the frames are not known ahead: no progress bar.
    ProgressBar progress(ownFrames, options.quiet || !ranks.first() || options.follow);
    // A solver on the GPU queues its passes on the renderer's context: there is
    // no host work to overlap with the render on a thread of its own.
    const bool pipelined = fields->fluidDevice() != "gpu" &&
                           (options.pipelining == "on" || (options.pipelining == "auto" && !context->info().rendersOnCpu()));
    std::optional<io::OutputFolder> output;
    const auto openOutput = [&]() -> io::OutputFolder& {
        output.emplace(outDir, options.force).recordScene(fingerprint);
        return *output;
    };
    try {
        try {
            runFrames(scene, *fields, frames, openOutput, progress, {pipelined, distribution, outDir});
        } catch (const gl::GpuMemoryError& error) {  // a size the scene asked for, too large for this machine
            throw InputError(scene.sourcePath + ": " + error.what());
        }
    } catch (const InputError& error) {
        // An input found bad on a later frame (a volume file's values):
        // the frames before it go too, as if it had been found first. (The
        // ranks of an MPI job write into shares of the folder while they
        // run: their files stay for --force.)
        if (!output || ranks.distributed()) throw;
        output->discard();
        throw InputError(std::string(error.what()) + " (the frames this run wrote before are removed)");
    }
    return 0;
}

}  // namespace eikon::app
