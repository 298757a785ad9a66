// Photon pass against closed forms: straight flight in uniform index,
// the inverse-square law, Beer–Lambert attenuation, and the energy balance.
// Tolerances are stated beside each check; photon counts are small enough
// for llvmpipe on two cores.
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <numeric>

namespace eikon {
namespace {

using namespace test;

// In uniform index ∇n = 0, so no integrator may bend a photon: every
// recorded vertex must lie on one line, perpendicular deviation ≤ 1e-6 of the
// grid size over a full crossing (float32 positions, Kahan-compensated), for
// every integrator, with uniform half-voxel and octree steps.
TEST(PhotonPhysics, PhotonInUniformIndexStaysStraight) {
    for (int integrator = 0; integrator < 3; ++integrator)
        for (auto policy : {TracerDesc::StepPolicy::Uniform, TracerDesc::StepPolicy::Octree}) {
            Scene scene = emptyScene(glm::dvec3(0.0), glm::dvec3(1.0), 32);
            scene.grid.smoothingSigmaVoxels = 0.0;
            scene.tracer.integrator = kIntegrators[integrator];
            scene.tracer.stepPolicy = policy;
            ObjectDesc filler;
            filler.kind = ObjectDesc::Kind::Box;
            filler.box = {glm::dvec3(-1.0), glm::dvec3(2.0)};
            filler.material.index = 1.33;
            scene.objects.push_back(filler);
            scene.lights.push_back(directionalLight({0.3, -1.0, 0.45}, 1.0));
            scene.render.photons = 1024;
            const TraceResult result = trace(scene, {.recordPathVertices = 256, .recordedPhotons = 1024});

            int checkedPhotons = 0;
            double worstDeviation = 0.0;
            for (int photon = 0; photon < 1024; ++photon) {
                std::vector<glm::dvec3> vertices;
                for (int v = 0; v < 256; ++v) {
                    const glm::vec4 vertex = result.paths[static_cast<std::size_t>(photon * 256 + v)];
                    if (vertex.w == 1.0f) vertices.emplace_back(vertex);
                }
                if (vertices.size() < 3) continue;  // missed the grid
                ++checkedPhotons;
                const glm::dvec3 origin = vertices.front();
                const glm::dvec3 direction = glm::normalize(vertices.back() - origin);
                for (const auto& vertex : vertices) {
                    const glm::dvec3 offset = vertex - origin;
                    worstDeviation =
                        std::max(worstDeviation, glm::length(offset - glm::dot(offset, direction) * direction));
                }
            }
            const std::string name = std::string("straight_ray_max_deviation_m_") + kIntegratorNames[integrator] +
                                     (policy == TracerDesc::StepPolicy::Octree ? "_octree" : "_uniform");
            test::reportFigure(name.c_str(), worstDeviation);
            EXPECT_GE(checkedPhotons, 16) << name;
            EXPECT_LE(worstDeviation, 1e-6) << name << " (grid size is 1 m)";
            EXPECT_LT(result.stats.maxInvariantError, 1e-6) << name;
        }
}

// A point light of intensity I = Φ/4π = 1 W/sr at height h above a square
// receiver: E = I·cosθ/d² = I·h/d³ per texel (RMS error ≤ 1%), and the
// received power equals I times the square's solid angle
// Ω = 4·asin(s² / (s² + h²)) for half-side s on the axis (≤ 0.5%).
TEST(PhotonPhysics, InverseSquareLaw) {
    Scene scene = test::inverseSquareScene();
    scene.render.photons = 1 << 20;
    const TraceResult result = trace(scene);

    const double height = 1.0, halfSide = 0.5;
    const double solidAngle = 4.0 * std::asin(halfSide * halfSide / (halfSide * halfSide + height * height));
    test::reportFigure("inverse_square_received_over_exact", result.stats.received.g / solidAngle);
    EXPECT_NEAR(result.stats.received.g / solidAngle, 1.0, 0.005);

    const auto& receiver = scene.receivers[0];
    double squaredError = 0.0;
    for (int j = 0; j < receiver.resolution; ++j)
        for (int i = 0; i < receiver.resolution; ++i) {
            // Texel centres in the receiver's own (u, v) frame; E depends only on the radius.
            const double u = ((i + 0.5) / receiver.resolution - 0.5) * receiver.size;
            const double v = ((j + 0.5) / receiver.resolution - 0.5) * receiver.size;
            const double distance = std::sqrt(height * height + u * u + v * v);
            const double expected = height / (distance * distance * distance);
            const double measured = result.map[static_cast<std::size_t>(3 * (j * receiver.resolution + i) + 1)];
            squaredError += std::pow(measured / expected - 1.0, 2);
        }
    const double rmsError = std::sqrt(squaredError / (receiver.resolution * receiver.resolution));
    test::reportFigure("inverse_square_texel_rms_relative_error", rmsError);
    EXPECT_LT(rmsError, 0.01);
}

// A directional beam through an absorbing slab of thickness L = 0.375 m with
// κ = (1, 3, 5) /m: the receiver below sees E0·exp(−κL) per channel (≤ 1%).
// The slab's faces lie on voxel faces, so coverage is exact and the check is
// of the tracer alone (voxelization has its own tests).
// A beam of 2 W/m² straight down through an absorbing slab 0.375 m thick
// (y in ±0.1875, on voxel faces of a 32³ grid) onto a floor receiver.
Scene absorbingSlabScene(const Rgb& extinction) {
    Scene scene = emptyScene(glm::dvec3(-0.5), glm::dvec3(0.5), 32);
    ObjectDesc slab;
    slab.kind = ObjectDesc::Kind::Box;
    slab.box = {glm::dvec3(-1.0, -0.1875, -1.0), glm::dvec3(1.0, 0.1875, 1.0)};
    slab.material.index = 1.0;
    slab.material.extinction = extinction;
    scene.objects.push_back(slab);
    scene.lights.push_back(directionalLight({0.0, -1.0, 0.0}, 2.0));
    scene.receivers.push_back(floorReceiver(-0.45, 0.5, 16));
    scene.render.photons = 1 << 18;
    return scene;
}

TEST(PhotonPhysics, BeerLambertThroughSlab) {
    const Rgb kappa(1.0, 3.0, 5.0);
    const TraceResult result = trace(absorbingSlabScene(kappa));

    for (int channel = 0; channel < 3; ++channel) {
        const double expected = 2.0 * std::exp(-kappa[channel] * 0.375);
        test::reportFigure(("beer_lambert_measured_over_exact_channel_" + std::to_string(channel)).c_str(),
                           channelMean(result.map, channel) / expected);
        EXPECT_NEAR(channelMean(result.map, channel) / expected, 1.0, 0.01) << "channel " << channel;
    }
    EXPECT_LT(result.stats.balanceError(), 1e-6);
}

// Deep attenuation past the power cutoff: κL = (10, 11, 12) through the same
// slab, every channel below the default cutoff of 1e-4 of a photon's power
// before it leaves the slab. Russian roulette keeps the estimate unbiased:
// E0·exp(−κL) per channel (4.5e-5 and below, within 2%: some 30 000 photons
// survive to the receiver), where stopping dim photons outright gave 0; the
// balance, the roulette's gain counted as a source, stays exact.
TEST(PhotonPhysics, RussianRouletteKeepsDeepAttenuationUnbiased) {
    const Rgb kappa = Rgb(10.0, 11.0, 12.0) / 0.375;
    const Scene scene = absorbingSlabScene(kappa);
    ASSERT_EQ(scene.tracer.powerCutoff, 1e-4);
    const TraceResult result = trace(scene);
    for (int channel = 0; channel < 3; ++channel) {
        const double expected = 2.0 * std::exp(-kappa[channel] * 0.375);
        const double ratio = channelMean(result.map, channel) / expected;
        test::reportFigure(("roulette_deep_slab_measured_over_exact_channel_" + std::to_string(channel)).c_str(), ratio);
        EXPECT_NEAR(ratio, 1.0, 0.02) << "channel " << channel;
    }
    EXPECT_GT(result.stats.rouletteGain.r, 0.0);
    EXPECT_GT(result.stats.photonsCutOff, 0u);
    EXPECT_LT(result.stats.balanceError(), 1e-6);
}

// Every watt emitted is absorbed, escapes, lands on a receiver, is cut off or
// blocked: the fixed-point tallies balance to 1e-6 even with extinction,
// refraction and a receiver seen from both sides.
TEST(PhotonPhysics, EnergyBalanceWithAbsorbingGlass) {
    Scene scene = emptyScene(glm::dvec3(-0.5), glm::dvec3(0.5), 32);
    ObjectDesc sphere;
    sphere.sphere = {glm::dvec3(0.0, 0.1, 0.0), 0.25};
    sphere.material.index = 1.5;
    sphere.material.extinction = Rgb(0.5, 2.0, 6.0);
    sphere.material.scattering = Rgb(0.2, 0.2, 0.2);
    scene.objects.push_back(sphere);
    LightDesc light;
    light.position = glm::dvec3(0.2, 0.45, 0.1);
    light.power = Rgb(5.0, 3.0, 1.0);
    scene.lights.push_back(light);
    scene.receivers.push_back(floorReceiver(-0.3, 0.8, 32));
    ReceiverDesc shade = floorReceiver(0.3, 0.2, 8);  // faces down, so light from above meets its back
    shade.point.x = -0.3;
    shade.normal = glm::dvec3(0.0, -1.0, 0.0);
    scene.receivers.push_back(shade);
    scene.render.photons = 1 << 17;
    const TraceResult result = trace(scene);

    const auto& s = result.stats;
    test::reportFigure("energy_balance_error_absorbing_glass", s.balanceError());
    EXPECT_LT(s.balanceError(), 1e-6);
    EXPECT_GT(s.absorbed.b / s.emitted.b, s.absorbed.r / s.emitted.r) << "blue is absorbed most";
    EXPECT_GT(s.received.r, 0.0);
    EXPECT_GT(s.photonsBlocked, 0u) << "light from above reaches the back of the downward-facing receiver";
}

// The same seed gives the same frame: identical fixed-point tallies and
// bit-identical receiver irradiance.
TEST(PhotonPhysics, SameSeedSameFrame) {
    Scene scene = emptyScene(glm::dvec3(-0.5), glm::dvec3(0.5), 24);
    ObjectDesc sphere;
    sphere.sphere = {glm::dvec3(0.0), 0.2};
    sphere.material.index = 1.5;
    scene.objects.push_back(sphere);
    scene.lights.push_back(directionalLight({0.1, -1.0, 0.0}, 1.0));
    scene.receivers.push_back(floorReceiver(-0.45, 0.8, 24));
    scene.render.photons = 1 << 15;
    const TraceResult first = trace(scene);
    const TraceResult second = trace(scene);
    EXPECT_EQ(first.stats.received, second.stats.received);
    EXPECT_EQ(first.stats.steps, second.stats.steps);
    EXPECT_EQ(first.map, second.map) << "receiver tallies are fixed point: bit-identical";
    scene.render.seed = 2;
    EXPECT_NE(trace(scene).stats.steps, first.stats.steps) << "another seed traces other photons";
}

}  // namespace
}  // namespace eikon
