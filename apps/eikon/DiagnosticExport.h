// A diagnostic's measurements as VTK ImageData (vtk/diagnostic_NNNNN.vti):
// one cell per pixel on the image plane, in metres from the camera's axis
// (x along the image's right, y its up, one pixel thick), rows from the
// bottom so that ParaView shows the picture upright; cell arrays
// `deflection` (rad, 2 components on those axes) and
// `optical_path_difference` (m).
#pragma once

#include "bridge/grid/NamedArrays.h"
#include "bridge/scene/Scene.h"
#include "render/stages/DiagnosticStage.h"

namespace eikon::app {

ExportFrame diagnosticExportFrame(const render::DiagnosticMeasurements& measured, const CameraDesc& camera);

}  // namespace eikon::app
