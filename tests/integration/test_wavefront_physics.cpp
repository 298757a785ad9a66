// The wavefront estimator (tracer.estimator "wavefront") against closed forms:
// the inverse-square law texel by texel, Beer–Lambert through a slab, and
// determinism — the same scene gives the same bits, frame after frame.
#include "render/graph/FrameRenderer.h"
#include "sim/voxelize/AnalyticVoxelizer.h"
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"

#include <gtest/gtest.h>

#include <cmath>

namespace eikon {
namespace {

using test::emptyScene;
using test::floorReceiver;

Scene byWavefront(Scene scene) {
    scene.tracer.estimator = TracerDesc::Estimator::Wavefront;
    for (ReceiverDesc& receiver : scene.receivers) receiver.filter = ReceiverDesc::Filter::None;
    return scene;
}

// E = I·h/d³ averaged over the texel (u, v) ± half a texel, by a 16×16
// midpoint rule (the texel mean, which the intensity law gives exactly; the
// centre value differs from it by ~4e-4 here).
double inverseSquareTexelMean(double height, double u, double v, double texel) {
    double sum = 0.0;
    for (int b = 0; b < 16; ++b)
        for (int a = 0; a < 16; ++a) {
            const double x = u + ((a + 0.5) / 16.0 - 0.5) * texel, z = v + ((b + 0.5) / 16.0 - 0.5) * texel;
            sum += height / std::pow(height * height + x * x + z * z, 1.5);
        }
    return sum / 256.0;
}

// A point light of intensity 1 W/sr 1 m above a 1 m receiver of 32² texels
// (the photon pass's InverseSquareLaw scene): texel RMS ≤ 0.1% of the texel
// mean (photons, 2^20 of them, reach 0.47%), and the received power I·Ω.
TEST(WavefrontPhysics, InverseSquareLaw) {
    Scene scene = test::inverseSquareScene();
    const test::TraceResult result = test::trace(byWavefront(scene));

    const double height = 1.0, halfSide = 0.5;
    const double solidAngle = 4.0 * std::asin(halfSide * halfSide / (halfSide * halfSide + height * height));
    test::reportFigure("wavefront_inverse_square_received_over_exact", result.stats.received.g / solidAngle);
    EXPECT_NEAR(result.stats.received.g / solidAngle, 1.0, 1e-4);
    const ReceiverDesc& receiver = scene.receivers[0];
    const double texel = receiver.size / receiver.resolution;
    double squaredError = 0.0;
    for (int j = 0; j < receiver.resolution; ++j)
        for (int i = 0; i < receiver.resolution; ++i) {
            const double u = ((i + 0.5) / receiver.resolution - 0.5) * receiver.size;
            const double v = ((j + 0.5) / receiver.resolution - 0.5) * receiver.size;
            const double measured = result.map[static_cast<std::size_t>(3 * (j * receiver.resolution + i) + 1)];
            squaredError += std::pow(measured / inverseSquareTexelMean(height, u, v, texel) - 1.0, 2);
        }
    const double rmsError = std::sqrt(squaredError / (receiver.resolution * receiver.resolution));
    test::reportFigure("wavefront_inverse_square_texel_rms_relative_error", rmsError);
    EXPECT_LE(rmsError, 1e-3);
    EXPECT_LE(result.stats.balanceError(), 1e-6);
    EXPECT_EQ(result.stats.wavefront.atLimit, 0u);
}

// A beam of 2 W/m² straight down through a slab 0.375 m thick of
// κ = (1, 3, 5) /m, faces on voxel faces (the photon pass's slab): every
// texel gets E0·exp(−κL), the trilinear κ across the faces integrating to the
// step's optical depth.
TEST(WavefrontPhysics, BeerLambertThroughSlab) {
    Scene scene = emptyScene(glm::dvec3(-0.5), glm::dvec3(0.5), 32);
    ObjectDesc slab;
    slab.kind = ObjectDesc::Kind::Box;
    slab.box = {glm::dvec3(-1.0, -0.1875, -1.0), glm::dvec3(1.0, 0.1875, 1.0)};
    slab.material.index = 1.0;
    const Rgb kappa(1.0, 3.0, 5.0);
    slab.material.extinction = kappa;
    scene.objects.push_back(slab);
    scene.lights.push_back(test::directionalLight({0.0, -1.0, 0.0}, 2.0));
    scene.receivers.push_back(floorReceiver(-0.45, 0.5, 16));
    const test::TraceResult result = test::trace(byWavefront(scene));
    const int n = scene.receivers[0].resolution;
    for (int channel = 0; channel < 3; ++channel) {
        const double expected = 2.0 * std::exp(-kappa[channel] * 0.375);
        double worst = 0.0;
        for (int t = 0; t < n * n; ++t)
            worst = std::max(worst, std::abs(result.map[static_cast<std::size_t>(3 * t + channel)] / expected - 1.0));
        test::reportFigure(("wavefront_beer_lambert_worst_texel_channel_" + std::to_string(channel)).c_str(), worst);
        EXPECT_LE(worst, 1e-4) << "channel " << channel;
    }
    EXPECT_LE(result.stats.balanceError(), 1e-6);
}

// A static scene relit is the same to the bit: nothing to flicker.
TEST(WavefrontPhysics, RelightsAreBitIdentical) {
    Scene scene = emptyScene(glm::dvec3(-0.5), glm::dvec3(0.5), 24);
    ObjectDesc sphere;
    sphere.kind = ObjectDesc::Kind::Sphere;
    sphere.sphere = {glm::dvec3(0.0, 0.1, 0.0), 0.2};
    sphere.material.index = 1.5;
    sphere.surface = ObjectDesc::Surface::Sharp;
    scene.objects.push_back(sphere);
    LightDesc light;
    light.position = glm::dvec3(0.05, 0.45, 0.0);
    light.power = Rgb(10.0);
    scene.lights.push_back(light);
    scene.receivers.push_back(floorReceiver(-0.45, 0.9, 48));
    scene = byWavefront(scene);
    test::glContext();
    const FieldSet fields = sim::voxelizeScene(scene);
    render::FrameRenderer renderer(scene, fields);
    renderer.render(fields);
    const std::vector<float> first = renderer.receivers().download(0);
    render::PhotonStats stats;
    renderer.relight(stats);
    EXPECT_EQ(renderer.receivers().download(0), first);
    EXPECT_GT(stats.wavefront.splits, 0u);
}

}  // namespace
}  // namespace eikon

