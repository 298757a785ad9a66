// A diagnostic frame's estimate of its own error (docs/accuracy.md,
// "Per-frame error estimates"), as ErrorEstimateStage estimates the camera
// image's discretisation: the scene's diagnostic is drawn small
// (ErrorEstimateStage::smallViewScene: 8 times narrower, one ray a pixel)
// with the scene's march — leapfrog, steps of render.step_voxels — and with
// the reference march — RK4, steps of ErrorEstimateStage::referenceStepVoxels
// (half the scene's, at most half a voxel) — and each output's relative L1
// change between the two is its estimate: the picture (I/I₀ per channel),
// and the measurements, deflection and optical path difference (every type
// but the shadowgraph, whose picture is its measurement) and BOS's
// displacement (per pixel the length of the vector's change over the
// length of the reference's). The reference's own error is a small part of
// the scene march's (fourth order in the deflection, and for the OPD's
// trapezoid rule a quarter at half the step). A diagnostic is
// deterministic: no noise. What both marches share — the grid's
// resolution, its trilinear δn and central-difference ∇n — is not seen.
#pragma once

#include "bridge/scene/Scene.h"
#include "render/stages/DiagnosticStage.h"
#include "render/stages/ErrorEstimateStage.h"
#include "render/stages/FieldTextures.h"

namespace eikon::render {

class DiagnosticErrorEstimate {
public:
    // The scene's diagnostic; frame: the stage that draws it (BOS: its dots' size).
    DiagnosticErrorEstimate(const Scene& scene, const FieldTextures& fields, const DiagnosticStage& frame);

    void setCamera(const CameraDesc& camera);
    void setVaryingVoxels(const VaryingVoxels& varying);  // DiagnosticStage::setVaryingVoxels
    ErrorEstimate run(const FieldTextures& fields);

private:
    double referenceStepVoxels_;
    DiagnosticStage march_, reference_;
};

}  // namespace eikon::render
