// The wavefront estimator in graded media with no surfaces, beside photons
// on the same sampled fields: the mirage's receiver map
// (verify/accuracy/MirageMap) against the reference tracer, and against
// closed forms a linear slab's catenaries on a receiver
// (verify/accuracy/CatenaryMap) and the map past a Luneburg lens's focus
// (verify/accuracy/LuneburgMap).
#include "render/graph/FrameRenderer.h"
#include "tests/integration/GlTestContext.h"
#include "verify/accuracy/AccuracyRun.h"
#include "verify/accuracy/CatenaryMap.h"
#include "verify/accuracy/LuneburgMap.h"
#include "verify/accuracy/MirageMap.h"
#include "verify/accuracy/ReceiverCaseScene.h"

#include <functional>
#include <string>
#include <utility>

#include <gtest/gtest.h>

namespace eikon {
namespace {

struct Comparison {
    double relativeL1 = 0.0;
    double milliseconds = 0.0;
};

using MapError = std::function<double(const std::vector<float>&)>;

Comparison compare(const Scene& scene, const FieldSet& fields, const MapError& error) {
    render::FrameRenderer renderer(scene, fields);
    renderer.render(fields);
    render::PhotonStats stats;
    const double ms = renderer.relight(stats).milliseconds;
    EXPECT_LE(stats.balanceError(), 1e-6);
    return {error(renderer.receivers().download(0)), ms};
}

// Both estimators on one scene and field, their errors and times reported
// under `prefix` (photons: the scene's 2²¹).
std::pair<Comparison, Comparison> compareEstimators(Scene scene, const FieldSet& fields, const MapError& error,
                                                    const std::string& prefix) {
    test::glContext();
    scene.tracer.stepPolicy = TracerDesc::StepPolicy::Uniform;
    scene.tracer.estimator = TracerDesc::Estimator::Wavefront;
    const Comparison wavefront = compare(scene, fields, error);
    scene.tracer.estimator = TracerDesc::Estimator::Photons;
    const Comparison photons = compare(scene, fields, error);
    test::reportFigure((prefix + "_wavefront_relative_l1").c_str(), wavefront.relativeL1);
    test::reportFigure((prefix + "_wavefront_ms").c_str(), wavefront.milliseconds);
    test::reportFigure((prefix + "_photons_2m_relative_l1").c_str(), photons.relativeL1);
    test::reportFigure((prefix + "_photons_2m_ms").c_str(), photons.milliseconds);
    return {wavefront, photons};
}

// The wavefront within 1% of the reference tracer's map and closer to it
// than 2²¹ photons; the times are reported beside the errors (not asserted).
TEST(WavefrontGraded, MirageReceiverMatchesTheReferenceTracer) {
    const std::vector<double> rows = accuracy::mirageReferenceRows();
    const Scene scene = accuracy::mirageMapScene();
    const FieldSet fields = accuracy::sampleIndexField(accuracy::mirageMapField(), scene.grid.spec(), 1.05);
    const auto [wavefront, photons] = compareEstimators(scene, fields, [&](const std::vector<float>& map) { return accuracy::mirageMapError(map, rows); }, "mirage");
    EXPECT_LE(wavefront.relativeL1, 0.01);
    EXPECT_LT(wavefront.relativeL1, photons.relativeL1);
}

// The catenaries of n = 1 + 0.25·y on a receiver: the wavefront within 1%
// of the closed form. Every row but the lowest lit one agrees to 1e-4; that
// one is 7% short, where rays grazing the grid's floor turn up onto the
// receiver beside rays that leave through it, and the patches torn there
// give their escaping corners' thirds away. 2²¹ photons, at about nine
// times the time, are closer there (both reported, neither asserted).
TEST(WavefrontGraded, LinearSlabCatenariesMatchTheClosedForm) {
    const std::vector<double> rows = accuracy::catenaryReferenceRows();
    const Scene scene = accuracy::catenaryMapScene();
    const FieldSet fields = accuracy::sampleIndexField(accuracy::catenaryMapField(), scene.grid.spec(), 1.0);
    const auto [wavefront, photons] = compareEstimators(scene, fields, [&](const std::vector<float>& map) { return accuracy::catenaryMapError(map, rows); }, "catenary");
    EXPECT_LE(wavefront.relativeL1, 0.01);
}

// Past the Luneburg lens's focus: both estimators against the closed form,
// the wavefront closer to it than 2²¹ photons (which take about nine times
// its time; reported, not asserted). Both stand on the floor of the 64³
// sampled lens, 5% (1.7% at 128³: second order in the voxel), which the
// wavefront adds nothing to and the photons add their noise to.
TEST(WavefrontGraded, LuneburgFocusMatchesTheClosedForm) {
    const std::vector<double> means = accuracy::luneburgMapTexelMeans();
    const Scene scene = accuracy::luneburgMapScene();
    const FieldSet fields = accuracy::sampleIndexField(accuracy::luneburgMapField(), scene.grid.spec(), 1.0);
    const auto [wavefront, photons] = compareEstimators(scene, fields, [&](const std::vector<float>& map) { return accuracy::texelMapError(map, means); }, "luneburg");
    EXPECT_LE(wavefront.relativeL1, 0.06);
    EXPECT_LT(wavefront.relativeL1, photons.relativeL1);
}

}  // namespace
}  // namespace eikon
