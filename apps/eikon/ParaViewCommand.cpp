#include "apps/eikon/ParaViewCommand.h"

#include "bridge/core/Error.h"
#include "io/scene/SceneParser.h"
#include "io/vtk/ParaViewState.h"

#include <filesystem>
#include <iostream>

namespace eikon::app {

namespace fs = std::filesystem;

void addParaViewCommand(CLI::App& app, ParaViewOptions& options) {
    CLI::App* paraview = app.add_subcommand(
        "paraview", "Write DIR/vtk/open_in_paraview.py: a ParaView state that opens a run's VTK export with the "
                    "scene's camera");
    paraview->add_option("dir", options.runDir, "Output folder of a run with VTK export (holding vtk/)")->required();
    paraview->add_option("scene", options.scenePath, "The scene the run rendered (its camera and grid)")->required();
    paraview->add_option("--set", options.overrides, "Override a scene value, e.g. --set camera.fov_deg=30");
}

int paraviewCommand(const ParaViewOptions& options) {
    const Scene scene = loadSceneFile(options.scenePath, options.overrides);
    const fs::path vtk = fs::path(options.runDir) / "vtk";
    const io::ParaViewState state = io::paraViewStateOf(scene);
    if (io::collectionsIn(vtk, io::kParaViewCollections).empty())
        throw InputError(options.runDir, "a run folder whose vtk/ holds fields.pvd, receivers.pvd, meshes.pvd or "
                                         "photon_paths.pvd (eikon run --vtk)",
                         fs::is_directory(vtk) ? "none of them" : "no vtk/ folder");
    io::writeParaViewState(vtk, state);
    std::cout << (vtk / "open_in_paraview.py").string() << "\n";
    return 0;
}

}  // namespace eikon::app
