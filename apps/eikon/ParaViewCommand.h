// `eikon paraview DIR SCENE`: (re)writes DIR/vtk/open_in_paraview.py, the
// ParaView state of a run's VTK export (io/vtk/ParaViewState.h), for the
// collections DIR/vtk holds, with SCENE's camera and grid. `eikon run`
// writes the same file itself; this one is for an export made before, or
// a camera changed since (--set camera.position=…). SCENE must be the scene
// the run rendered, with the same --set, camera and export aside: the run
// recorded its fingerprint in DIR/.eikon-run (io/scene/SceneFingerprint.h),
// and another scene is refused (exit 2) before anything is written.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace eikon::app {

struct ParaViewOptions {
    std::string runDir;
    std::string scenePath;
    std::vector<std::string> overrides;
};

void addParaViewCommand(CLI::App& app, ParaViewOptions& options);
int paraviewCommand(const ParaViewOptions& options);

}  // namespace eikon::app
