// The wavefront estimator in a graded medium with no surfaces: an
// exponential mirage layer (n = 1.05 − 0.05·exp(−y/0.1 m), the accuracy
// suite's mirage) under a beam along (1, −0.15, 0), seen on a receiver across
// its far end. Ground truth from the double-precision reference tracer
// (verify/reference, Dormand–Prince 5(4) on the closed-form field): the
// problem is uniform along z, so a dense fan of reference rays through the
// grid's x = 0 and top faces, each carrying the beam's flux through its
// strip of face, binned by where it crosses the receiver's plane, gives each
// row's irradiance. Both estimators against it, on the same sampled field.
#include "render/graph/FrameRenderer.h"
#include "tests/integration/GlTestContext.h"
#include "verify/accuracy/AccuracyRun.h"
#include "verify/reference/AnalyticFields.h"
#include "verify/reference/ReferenceTracer.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace eikon {
namespace {

constexpr double kLength = 2.56, kHeight = 0.48, kDepth = 0.64;  // m: the grid
constexpr double kPlaneX = 2.4;                                   // the receiver's plane
constexpr int kRows = 48;
const glm::dvec3 kBeam = glm::normalize(glm::dvec3(1.0, -0.15, 0.0));

const reference::MirageField& mirage() {
    static const reference::MirageField field(1.05, 0.05, 0.1);
    return field;
}

Scene mirageScene(TracerDesc::Estimator estimator, long long photons) {
    Scene scene;
    scene.grid.boundsMin = glm::dvec3(0.0);
    scene.grid.boundsMax = glm::dvec3(kLength, kHeight, kDepth);
    scene.grid.resolution = glm::ivec3(256, 48, 64);
    scene.grid.smoothingSigmaVoxels = 0.0;
    scene.medium.index = 1.05;
    scene.render.width = 8;
    scene.render.height = 8;
    scene.render.photons = photons;
    LightDesc light;
    light.kind = LightDesc::Kind::Directional;
    light.direction = kBeam;
    light.irradiance = Rgb(1.0);
    scene.lights.push_back(light);
    ReceiverDesc receiver;
    receiver.point = glm::dvec3(kPlaneX, 0.5 * kHeight, 0.5 * kDepth);
    receiver.normal = glm::dvec3(-1.0, 0.0, 0.0);
    receiver.size = kHeight;
    receiver.resolution = kRows;
    receiver.filter = ReceiverDesc::Filter::None;
    scene.receivers.push_back(receiver);
    // The graded field comes as sampled fields, which the emission region
    // does not see: an invisible box over the grid makes the light cover it
    // all (light bent onto the receiver would miss it otherwise).
    ObjectDesc cover;
    cover.kind = ObjectDesc::Kind::Box;
    cover.box = {scene.grid.boundsMin, scene.grid.boundsMax};
    cover.material.index = scene.medium.index;
    cover.surface = ObjectDesc::Surface::Smooth;
    scene.objects.push_back(cover);
    scene.tracer.estimator = estimator;
    scene.tracer.stepPolicy = TracerDesc::StepPolicy::Uniform;
    scene.tracer.stepVoxels = 0.5;
    return scene;
}

// Row j of the receiver (its v axis is −y, so row 0 is at the top).
int rowOf(double y) { return static_cast<int>(std::floor((0.5 - (y - 0.5 * kHeight) / kHeight) * kRows)); }

// Irradiance (W/m²) of each row by the reference tracer: rays entering the x
// = 0 face and the top face, each with the flux E0·|d·n| through its strip.
std::vector<double> referenceRows() {
    reference::ReferenceOptions options;
    options.tolerance = 1e-10;
    const reference::ReferenceTracer tracer(mirage(), options);
    std::vector<double> power(kRows, 0.0);  // W per metre of z
    auto follow = [&](glm::dvec3 entry, double flux) {
        const reference::ReferenceResult result = tracer.trace(tracer.start(entry, kBeam), 10.0, [](const reference::RayState& s) {
            return std::min({kPlaneX - s.x.x, s.x.y, kHeight - s.x.y});
        });
        if (!result.eventHit || std::abs(result.state.x.x - kPlaneX) > 1e-7) return;  // left the grid first
        const int row = rowOf(result.state.x.y);
        if (row >= 0 && row < kRows) power[static_cast<std::size_t>(row)] += flux;
    };
    const int sideRays = 24'000, topRays = 60'000;
    for (int k = 0; k < sideRays; ++k) {
        const double y = (k + 0.5) / sideRays * kHeight;
        follow({0.0, y, 0.5 * kDepth}, kBeam.x * kHeight / sideRays);
    }
    for (int k = 0; k < topRays; ++k) {
        const double x = (k + 0.5) / topRays * kPlaneX;
        follow({x, kHeight - 1e-9, 0.5 * kDepth}, -kBeam.y * kPlaneX / topRays);
    }
    for (double& row : power) row /= kHeight / kRows;
    return power;
}

struct Comparison {
    double relativeL1 = 0.0;
    double milliseconds = 0.0;
};

// The green map of `scene` on `fields` against the rows, over the texels
// whose z lies more than 4 cm inside the grid (the beam enters the side
// faces there too).
Comparison compare(const Scene& scene, const FieldSet& fields, const std::vector<double>& rows) {
    render::FrameRenderer renderer(scene, fields);
    renderer.render(fields);
    render::PhotonStats stats;
    const double ms = renderer.relight(stats).milliseconds;
    EXPECT_LE(stats.balanceError(), 1e-6);
    const std::vector<float> map = renderer.receivers().download(0);
    double difference = 0.0, total = 0.0;
    for (int j = 0; j < kRows; ++j)
        for (int i = 0; i < kRows; ++i) {
            const double z = kDepth - (0.5 * kDepth - 0.5 * kHeight + (i + 0.5) / kRows * kHeight);
            if (z < 0.04 || z > kDepth - 0.04) continue;
            const double measured = map[static_cast<std::size_t>(3 * (j * kRows + i) + 1)];
            difference += std::abs(measured - rows[static_cast<std::size_t>(j)]);
            total += rows[static_cast<std::size_t>(j)];
        }
    return {difference / total, ms};
}

// The wavefront within 1% of the reference tracer's map and closer to it
// than 2²¹ photons; the times are reported beside the errors (not asserted).
TEST(WavefrontGraded, MirageReceiverMatchesTheReferenceTracer) {
    test::glContext();
    const std::vector<double> rows = referenceRows();
    const Scene wavefrontScene = mirageScene(TracerDesc::Estimator::Wavefront, 1);
    const FieldSet fields = accuracy::sampleIndexField(mirage(), wavefrontScene.grid.spec(), 1.05);
    const Comparison wavefront = compare(wavefrontScene, fields, rows);
    const Comparison photons = compare(mirageScene(TracerDesc::Estimator::Photons, 1 << 21), fields, rows);
    test::reportFigure("mirage_wavefront_relative_l1", wavefront.relativeL1);
    test::reportFigure("mirage_wavefront_ms", wavefront.milliseconds);
    test::reportFigure("mirage_photons_2m_relative_l1", photons.relativeL1);
    test::reportFigure("mirage_photons_2m_ms", photons.milliseconds);
    EXPECT_LE(wavefront.relativeL1, 0.01);
    EXPECT_LT(wavefront.relativeL1, photons.relativeL1);
}

}  // namespace
}  // namespace eikon

