#include "apps/eikon/ParaViewCommand.h"

#include "bridge/core/Error.h"
#include "io/files/OutputFolder.h"
#include "io/files/RunJournal.h"
#include "io/scene/SceneFingerprint.h"
#include "io/scene/SceneParser.h"
#include "io/vtk/ParaViewState.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

namespace eikon::app {

namespace fs = std::filesystem;

void addParaViewCommand(CLI::App& app, ParaViewOptions& options) {
    CLI::App* paraview = app.add_subcommand(
        "paraview", "Write DIR/vtk/open_in_paraview.py: a ParaView state that opens a run's VTK export with the "
                    "scene's camera");
    paraview->add_option("dir", options.runDir, "Output folder of a run with VTK export (holding vtk/)")->required();
    paraview->add_option("scene", options.scenePath,
                        "The scene the run rendered, with its --set (checked against the run's record; its camera "
                        "and grid go into the state)")
        ->required();
    paraview->add_option("--set", options.overrides, "Override a scene value, e.g. --set camera.fov_deg=30");
}

namespace {

// The scene fingerprint the run's journal holds; nullopt where there is no
// journal or it holds none (an older eikon's run).
std::optional<std::string> recordedScene(const fs::path& runDir) {
    std::ifstream journal(runDir / io::OutputFolder::kJournalName, std::ios::binary);
    if (!journal) return std::nullopt;
    std::stringstream text;
    text << journal.rdbuf();
    return io::journalScene(text.str());
}

// SCENE (with --set) must be the scene the run rendered, camera and export
// aside (io/scene/SceneFingerprint.h): a state with another scene's grid
// would put its slice and outline where the run's fields are not.
void requireTheRunsScene(const ParaViewOptions& options, const nlohmann::json& document) {
    const std::optional<std::string> recorded = recordedScene(options.runDir);
    if (!recorded) {
        std::cerr << "eikon: warning: " << options.runDir
                  << " holds no record of the scene its run rendered (a run of an older eikon): " << options.scenePath
                  << " is taken as that scene unchecked\n";
        return;
    }
    const std::string fingerprint = sceneFingerprint(document);
    if (fingerprint != *recorded)
        throw InputError(options.scenePath + ": expected the scene the run in " + options.runDir +
                         " rendered, with the same --set (camera and export keys may differ; fingerprint " +
                         *recorded + " in " + (fs::path(options.runDir) / io::OutputFolder::kJournalName).string() +
                         "), found another scene (fingerprint " + fingerprint + ")");
}

}  // namespace

int paraviewCommand(const ParaViewOptions& options) {
    const nlohmann::json document = loadSceneDocument(options.scenePath, options.overrides);
    const Scene scene = parseScene(document, options.scenePath);
    const fs::path vtk = fs::path(options.runDir) / "vtk";
    const io::ParaViewState state = io::paraViewStateOf(scene);
    if (io::collectionsIn(vtk, io::kParaViewCollections).empty())
        throw InputError(options.runDir, "a run folder whose vtk/ holds fields.pvd, receivers.pvd, meshes.pvd or "
                                         "photon_paths.pvd (eikon run --vtk)",
                         fs::is_directory(vtk) ? "none of them" : "no vtk/ folder");
    requireTheRunsScene(options, document);
    io::writeParaViewState(vtk, state);
    std::cout << (vtk / "open_in_paraview.py").string() << "\n";
    return 0;
}

}  // namespace eikon::app
