// A ParaView Python state for a run's VTK export (docs/paraview.md):
// DIR/vtk/open_in_paraview.py opens the collections that exist — fields,
// receivers, meshes, photon paths, and a diagnostic's image plane in a view
// of its own — with colour maps for each and the scene's camera. Run it with `pvpython open_in_paraview.py [PICTURE.png]`
// (a picture is saved when named) or from ParaView's Python shell. The
// fields show as a slice through the grid's centre, coloured by δn where it
// is exported (n itself spans 1e-5 in a mirage, so an `index` bar reads
// 1.0e+00 at both ends; its labels get six decimals when it is the one shown).
#pragma once

#include "bridge/scene/Scene.h"

#include <filesystem>
#include <string>
#include <vector>

namespace eikon::io {

// Every collection a run's VTK export can hold, in the order the script opens them.
inline const std::vector<std::string> kParaViewCollections{"fields", "receivers", "meshes", "photon_paths",
                                                          "diagnostic"};

// The collections of `names` whose NAME.pvd exists in vtkFolder.
std::vector<std::string> collectionsIn(const std::filesystem::path& vtkFolder, std::vector<std::string> names);

struct ParaViewState {
    CameraDesc camera;
    double parallelScale = 0.0;  // an orthographic camera's half height (m); 0 for a perspective one
    glm::dvec3 gridMin{0.0}, gridMax{1.0};
    // The diagnostic's array its view is coloured by: what the instrument shows.
    std::string diagnosticArray = "optical_path_difference";
    // Collections in DIR/vtk the script opens, as NAME for NAME.pvd: any of
    // kParaViewCollections.
    std::vector<std::string> collections = kParaViewCollections;
    // fields_static.vti holds the arrays the run never changes
    // (io/vtk/VtkSeriesWriter.h): the script merges them into the fields.
    bool staticFields = false;
};

// The scene's camera, grid and diagnostic, every collection listed.
ParaViewState paraViewStateOf(const Scene& scene);

// The script's text.
std::string paraviewStateScript(const ParaViewState& state);

// Writes vtkFolder/open_in_paraview.py atomically, listing only the
// collections whose .pvd exists there, and the static fields where their
// file does.
void writeParaViewState(const std::filesystem::path& vtkFolder, ParaViewState state);

}  // namespace eikon::io
