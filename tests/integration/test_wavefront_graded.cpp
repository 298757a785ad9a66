// The wavefront estimator in a graded medium with no surfaces: the mirage's
// receiver map (verify/accuracy/MirageMap) against the reference tracer,
// beside photons on the same sampled field.
#include "render/graph/FrameRenderer.h"
#include "tests/integration/GlTestContext.h"
#include "verify/accuracy/AccuracyRun.h"
#include "verify/accuracy/MirageMap.h"

#include <gtest/gtest.h>

namespace eikon {
namespace {

struct Comparison {
    double relativeL1 = 0.0;
    double milliseconds = 0.0;
};

Comparison compare(const Scene& scene, const FieldSet& fields, const std::vector<double>& rows) {
    render::FrameRenderer renderer(scene, fields);
    renderer.render(fields);
    render::PhotonStats stats;
    const double ms = renderer.relight(stats).milliseconds;
    EXPECT_LE(stats.balanceError(), 1e-6);
    return {accuracy::mirageMapError(renderer.receivers().download(0), rows), ms};
}

// The wavefront within 1% of the reference tracer's map and closer to it
// than 2²¹ photons; the times are reported beside the errors (not asserted).
TEST(WavefrontGraded, MirageReceiverMatchesTheReferenceTracer) {
    test::glContext();
    const std::vector<double> rows = accuracy::mirageReferenceRows();
    Scene scene = accuracy::mirageMapScene();
    scene.tracer.stepPolicy = TracerDesc::StepPolicy::Uniform;
    const FieldSet fields = accuracy::sampleIndexField(accuracy::mirageMapField(), scene.grid.spec(), 1.05);
    scene.tracer.estimator = TracerDesc::Estimator::Wavefront;
    const Comparison wavefront = compare(scene, fields, rows);
    scene.tracer.estimator = TracerDesc::Estimator::Photons;
    const Comparison photons = compare(scene, fields, rows);
    test::reportFigure("mirage_wavefront_relative_l1", wavefront.relativeL1);
    test::reportFigure("mirage_wavefront_ms", wavefront.milliseconds);
    test::reportFigure("mirage_photons_2m_relative_l1", photons.relativeL1);
    test::reportFigure("mirage_photons_2m_ms", photons.milliseconds);
    EXPECT_LE(wavefront.relativeL1, 0.01);
    EXPECT_LT(wavefront.relativeL1, photons.relativeL1);
}

}  // namespace
}  // namespace eikon
