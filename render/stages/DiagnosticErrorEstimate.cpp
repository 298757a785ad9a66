#include "render/stages/DiagnosticErrorEstimate.h"

#include "gl/GlContext.h"
#include "render/stages/RelativeChange.h"

#include <chrono>

namespace eikon::render {

namespace {

// The scene drawn small, its BOS background as large as the frame's.
Scene smallDiagnosticScene(const Scene& scene, const DiagnosticStage& frame) {
    Scene small = ErrorEstimateStage::smallViewScene(scene);
    if (small.diagnostic->type != DiagnosticDesc::Type::Bos) return small;
    small.diagnostic->dotDiameter = frame.dotDiameter();
    if (small.diagnostic->patternImage) small.diagnostic->patternWidth = frame.patternWidth();
    return small;
}

Scene referenceMarchScene(const Scene& scene, const DiagnosticStage& frame) {
    Scene reference = smallDiagnosticScene(scene, frame);
    reference.render.stepVoxels = ErrorEstimateStage::referenceStepVoxels(scene);
    return reference;
}

}  // namespace

DiagnosticErrorEstimate::DiagnosticErrorEstimate(const Scene& scene, const FieldTextures& fields,
                                                 const DiagnosticStage& frame)
    : referenceStepVoxels_(ErrorEstimateStage::referenceStepVoxels(scene)),
      march_(smallDiagnosticScene(scene, frame), fields),
      reference_(referenceMarchScene(scene, frame), fields, TracerDesc::Integrator::Rk4) {}

void DiagnosticErrorEstimate::setCamera(const CameraDesc& camera) {
    march_.setCamera(camera);
    reference_.setCamera(camera);
}

void DiagnosticErrorEstimate::setVaryingVoxels(const VaryingVoxels& varying) {
    march_.setVaryingVoxels(varying);
    reference_.setVaryingVoxels(varying);
}

ErrorEstimate DiagnosticErrorEstimate::run(const FieldTextures& fields) {
    const auto start = std::chrono::steady_clock::now();
    ErrorEstimate estimate;
    estimate.referenceStepVoxels = referenceStepVoxels_;
    march_.run(fields);
    reference_.run(fields);
    estimate.discretisation.image = relativeL1OfRgb(march_.downloadHdr(), reference_.downloadHdr());
    const DiagnosticMeasurements measured = march_.downloadMeasurements();
    const DiagnosticMeasurements referenced = reference_.downloadMeasurements();
    if (!referenced.deflection.empty()) {
        estimate.discretisation.deflection = relativeL1OfVectors(measured.deflection, referenced.deflection, 2);
        estimate.discretisation.opticalPathDifference =
            relativeL1OfVectors(measured.opticalPathDifference, referenced.opticalPathDifference, 1);
    }
    if (!referenced.displacement.empty())
        estimate.discretisation.displacement = relativeL1OfVectors(measured.displacement, referenced.displacement, 2);
    glFinish();
    estimate.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return estimate;
}

}  // namespace eikon::render
