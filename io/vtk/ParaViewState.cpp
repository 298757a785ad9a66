#include "io/vtk/ParaViewState.h"

#include "io/files/AtomicFile.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <utility>
#include <cmath>
#include <cstdio>

namespace eikon::io {

namespace {

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

std::string list(const glm::dvec3& v) { return "[" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + "]"; }

bool opens(const ParaViewState& state, const std::string& name) {
    return std::find(state.collections.begin(), state.collections.end(), name) != state.collections.end();
}

// The script's fixed part: helpers, then one block per collection.
constexpr const char* kPrologue = R"(# Written by eikon: opens this run's VTK export in ParaView (5.10 or later).
#   pvpython open_in_paraview.py [PICTURE.png]   (saves PICTURE.png when named)
#   ParaView: View > Python Shell > Run Script
import os
import sys
from paraview.simple import *

here = os.path.dirname(os.path.abspath(globals().get('__file__', 'open_in_paraview.py')))
view = GetActiveViewOrCreate('RenderView')


def collection(name):
    return PVDReader(registrationName=name, FileName=os.path.join(here, name + '.pvd'))


def colour(source, display, association, array, preset, corner, target=None):
    target = target or view
    data = source.CellData if association == 'CELLS' else source.PointData
    components = data[array].GetNumberOfComponents()
    ColorBy(display, (association, array, 'Magnitude') if components > 1 else (association, array))
    lut = GetColorTransferFunction(array)
    lut.ApplyPreset(preset, True)
    display.RescaleTransferFunctionToDataRange(True, False)
    display.SetScalarBarVisibility(target, True)
    GetScalarBar(lut, target).WindowLocation = corner
    return lut

)";

constexpr const char* kStaticFields = R"(
# Arrays the run never changes are written once, in fields_static.vti: they
# join every frame's own (the series first: it carries the time).
fields = AppendAttributes(registrationName='fields and unchanging arrays',
                          Input=[collection('fields'),
                                 XMLImageDataReader(registrationName='fields_static',
                                                    FileName=[os.path.join(here, 'fields_static.vti')])])
)";

constexpr const char* kFields = R"(
# The fields: the grid's outline and a slice through its centre, facing the
# camera, coloured by the first of these that the export holds and that
# varies by more than 1e-9 in SI units over frame 0 (sharp objects leave δn 0).
fields.UpdatePipeline()
outline = Show(fields, view)
outline.SetRepresentationType('Outline')


def varies(name):
    low, high = fields.CellData[name].GetRange(-1)
    return high - low > 1e-9


names = [n for n in fields.CellData.keys() if varies(n)]
shown = next((n for n in ('delta_index', 'fluence', 'temperature', 'density', 'extinction', 'index') if n in names),
             names[0] if names else None)
cut = Slice(registrationName='fields slice', Input=fields)
cut.SliceType = 'Plane'
cut.SliceType.Origin = grid_centre
cut.SliceType.Normal = slice_normal
cut.UpdatePipeline()
cut_display = Show(cut, view)
if not shown:
    Hide(cut, view)
else:
    colour(cut, cut_display, 'CELLS', shown, 'Viridis (matplotlib)', 'Lower Left Corner')
    if shown == 'index':  # n spans 1e-5 in a mirage: six decimals, not 1.0e+00 at both ends
        bar = GetScalarBar(GetColorTransferFunction('index'), view)
        bar.AutomaticLabelFormat = 0
        bar.LabelFormat = '%-#.6f'
        bar.RangeLabelFormat = '%-#.6f'
)";

constexpr const char* kReceivers = R"(
# Receivers: each texel of an irradiance map a quad, W/m^2.
receivers = collection('receivers')
receivers.UpdatePipeline()
colour(receivers, Show(receivers, view), 'CELLS', 'irradiance', 'Inferno (matplotlib)', 'Lower Right Corner')
)";

constexpr const char* kMeshes = R"(
# Meshes and the water surface, translucent so what is behind them shows.
meshes = collection('meshes')
meshes.UpdatePipeline()
mesh_display = Show(meshes, view)
mesh_display.DiffuseColor = [0.8, 0.9, 1.0]
mesh_display.Opacity = 0.3
)";

constexpr const char* kPaths = R"(
# Photon paths, coloured by the power they carry (W).
paths = collection('photon_paths')
paths.UpdatePipeline()
colour(paths, Show(paths, view), 'POINTS', 'power', 'Cool to Warm', 'Upper Right Corner')
)";

constexpr const char* kDiagnostic = R"(
# The diagnostic: what its rays measured, on the image plane (metres from
# the camera's axis, x right, y up), in a view of its own beside the scene.
diagnostic = collection('diagnostic')
diagnostic.UpdatePipeline()
layout = GetLayout(view)
layout.SplitHorizontal(0, 0.5)
plane_view = CreateView('RenderView')
AssignViewToLayout(view=plane_view, layout=layout, hint=2)
plane_view.InteractionMode = '2D'
colour(diagnostic, Show(diagnostic, plane_view), 'CELLS', diagnostic_array, 'Grayscale', 'Lower Right Corner',
       plane_view)
ResetCamera(plane_view)
SetActiveView(view)
)";

constexpr const char* kEpilogue = R"(
GetAnimationScene().UpdateAnimationUsingDataTimeSteps()
# paraview.simple resets the camera to the data on a script's first Render()
# (pvbatch, pvpython): render once, then set the scene's camera.
Render(view)
view.CameraPosition = camera_position
view.CameraFocalPoint = camera_target
view.CameraViewUp = camera_up
view.CameraViewAngle = camera_fov_deg
if camera_parallel_scale > 0:  # an orthographic camera
    view.CameraParallelProjection = 1
    view.CameraParallelScale = camera_parallel_scale
Render(view)
if len(sys.argv) > 1:
    SaveScreenshot(sys.argv[1], view, ImageResolution=[800, 600])
)";

}  // namespace

std::string paraviewStateScript(const ParaViewState& state) {
    const glm::dvec3 forward = glm::normalize(state.camera.target - state.camera.position);
    glm::dvec3 normal{0.0};
    const glm::dvec3 reach = glm::abs(forward);
    normal[reach.x >= reach.y && reach.x >= reach.z ? 0 : reach.y >= reach.z ? 1 : 2] = 1.0;
    std::string script = kPrologue;
    script += "# The scene's grid and camera.\n";
    script += "grid_centre = " + list(0.5 * (state.gridMin + state.gridMax)) + "\n";
    script += "slice_normal = " + list(normal) + "\n";
    script += "camera_position = " + list(state.camera.position) + "\n";
    script += "camera_target = " + list(state.camera.target) + "\n";
    script += "camera_up = " + list(state.camera.up) + "\n";
    script += "camera_fov_deg = " + number(state.camera.fovDeg) + "\n";
    script += "camera_parallel_scale = " + number(state.parallelScale) + "\n";
    script += "diagnostic_array = '" + state.diagnosticArray + "'\n";
    if (opens(state, "fields")) {
        script += state.staticFields ? kStaticFields : "\nfields = collection('fields')\n";
        script += kFields;
    }
    if (opens(state, "receivers")) script += kReceivers;
    if (opens(state, "meshes")) script += kMeshes;
    if (opens(state, "photon_paths")) script += kPaths;
    if (opens(state, "diagnostic")) script += kDiagnostic;
    script += kEpilogue;
    return script;
}

ParaViewState paraViewStateOf(const Scene& scene) {
    ParaViewState state;
    state.camera = scene.camera;
    if (scene.camera.orthographic())
        state.parallelScale = 0.5 * scene.camera.widthM * scene.render.height / scene.render.width;
    state.gridMin = scene.grid.boundsMin;
    state.gridMax = scene.grid.boundsMax;
    if (scene.diagnostic) {
        switch (scene.diagnostic->type) {
            case DiagnosticDesc::Type::Interferometry: state.diagnosticArray = "optical_path_difference"; break;
            case DiagnosticDesc::Type::Schlieren: state.diagnosticArray = "deflection"; break;
            case DiagnosticDesc::Type::Shadowgraph: state.diagnosticArray = "relative_irradiance"; break;
            case DiagnosticDesc::Type::Bos: state.diagnosticArray = "displacement"; break;
        }
    }
    return state;
}

std::vector<std::string> collectionsIn(const std::filesystem::path& vtkFolder, std::vector<std::string> names) {
    std::erase_if(names, [&](const std::string& name) { return !std::filesystem::exists(vtkFolder / (name + ".pvd")); });
    return names;
}

void writeParaViewState(const std::filesystem::path& vtkFolder, ParaViewState state) {
    state.collections = collectionsIn(vtkFolder, std::move(state.collections));
    state.staticFields = std::filesystem::exists(vtkFolder / "fields_static.vti");
    writeFileAtomically(vtkFolder / "open_in_paraview.py", paraviewStateScript(state));
}

}  // namespace eikon::io
