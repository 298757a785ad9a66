// A diagnostic's measurements as VTK ImageData (vtk/diagnostic_NNNNN.vti):
// one cell per pixel on the image plane, in metres from the camera's axis
// (perspective: at unit distance from the pinhole), x along the image's
// right, y its up, one pixel thick, rows from the bottom so that ParaView
// shows the picture upright; cell arrays, those the instrument measures:
// `deflection` (rad, 2 components on those axes), `optical_path_difference`
// (m), `displacement` (BOS: px, 2 components) and `relative_irradiance`
// (shadowgraph: I/I₀, RGB).
#pragma once

#include "bridge/grid/NamedArrays.h"
#include "bridge/scene/Scene.h"
#include "render/stages/DiagnosticStage.h"

namespace eikon::app {

ExportFrame diagnosticExportFrame(const render::DiagnosticMeasurements& measured, const CameraDesc& camera);

}  // namespace eikon::app
