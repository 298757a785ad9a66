// The photon tracer against closed forms on its own fields: the catenary in
// a linear-gradient slab, Beer–Lambert in the stored fluence, adaptive versus
// uniform steps on the glass-sphere caustic, spot-light power and dispersion.
#include "sim/voxelize/AnalyticVoxelizer.h"
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace eikon {
namespace {

using namespace test;

// n = a + b·y on a 128×64×8 grid of 1 cm voxels (n_ref = a = 1, so δn = b·y).
FieldSet linearSlab(const Scene& scene, double gradient) {
    FieldSet fields;
    fields.grid = scene.grid.spec();
    fields.referenceIndex = 1.0;
    fields.deltaIndex.resize(fields.grid.cellCount());
    for (int k = 0; k < fields.grid.resolution.z; ++k)
        for (int j = 0; j < fields.grid.resolution.y; ++j)
            for (int i = 0; i < fields.grid.resolution.x; ++i)
                fields.deltaIndex[fields.grid.linearIndex(i, j, k)] =
                    static_cast<float>(gradient * fields.grid.cellCentre(i, j, k).y);
    fields.indexVersion = 1;
    return fields;
}

// In a layered medium n(y) the horizontal component of v = n·dx/ds is
// invariant (n·cosθ = C), and for n = a + b·y the path is the catenary
//   n(y(x)) = C·cosh(b·(x − x_v)/C),  x_v = x0 + (C/b)·acosh(n0/C),
// for a ray entering at (x0, y0) heading down. After 100 voxels of travel
// every recorded vertex must be within 0.1 voxel of it (leapfrog and RK4,
// half-voxel steps; Euler is reported, first order).
TEST(TracerAccuracy, LinearGradientSlabFollowsCatenary) {
    const double a = 1.0, b = 0.25, voxel = 0.01;
    for (int integrator = 0; integrator < 3; ++integrator) {
        Scene scene = emptyScene(glm::dvec3(0.0), glm::dvec3(1.28, 0.64, 0.08), 1);
        scene.grid.resolution = glm::ivec3(128, 64, 8);
        scene.grid.smoothingSigmaVoxels = 0.0;
        scene.tracer.integrator = kIntegrators[integrator];
        scene.tracer.stepPolicy = TracerDesc::StepPolicy::Uniform;
        scene.lights.push_back(directionalLight({1.0, -0.2, 0.0}, 1.0));
        scene.render.photons = 4096;
        const FieldSet fields = linearSlab(scene, b);
        const TraceResult result = traceFields(scene, fields, {.recordPathVertices = 600, .recordedPhotons = 4096});

        double worst = 0.0;
        int checked = 0;
        for (int photon = 0; photon < 4096; ++photon) {
            const glm::vec4* path = &result.paths[static_cast<std::size_t>(photon) * 600];
            // path[0] is the emission point outside the grid; path[1] the entry.
            if (path[1].w != 1.0f || path[2].w != 1.0f) continue;
            const glm::dvec3 entry(path[1]);
            const glm::dvec3 direction = glm::normalize(glm::dvec3(1.0, -0.2, 0.0));
            const double n0 = a + b * entry.y;
            const double invariant = n0 * direction.x;
            const double vertexX = entry.x + invariant / b * std::acosh(n0 / invariant);
            const double vertexY = (invariant - a) / b;
            if (vertexY < 0.05) continue;  // would touch the bottom faces, where the field is clamped
            bool reached = false;
            for (int v = 2; v < 600 && path[v].w == 1.0f; ++v) {
                const glm::dvec3 x(path[v]);
                if (x.x >= 1.28 - 1e-6 || x.y >= 0.64 - 1e-6) break;  // left the grid
                if (glm::length(x - entry) < 100 * voxel) continue;
                const double predictedY = (invariant * std::cosh(b * (x.x - vertexX) / invariant) - a) / b;
                worst = std::max(worst, std::abs(x.y - predictedY));
                reached = true;
            }
            checked += reached;
        }
        const std::string name = std::string("catenary_max_error_voxels_") + kIntegratorNames[integrator];
        reportFigure(name.c_str(), worst / voxel);
        EXPECT_GE(checked, 20) << name;
        if (kIntegrators[integrator] != TracerDesc::Integrator::Euler) {
            EXPECT_LT(worst / voxel, 0.1) << name;
        }
    }
}

// A collimated beam of irradiance E0 straight down through a homogeneous
// absorbing medium: the stored fluence at depth d is E0·exp(−κd) per channel
// (within 2%, on cells away from the faces).
TEST(TracerAccuracy, FluenceFollowsBeerLambert) {
    Scene scene = emptyScene(glm::dvec3(-0.25, 0.0, -0.25), glm::dvec3(0.25, 0.5, 0.25), 20);
    scene.grid.resolution = glm::ivec3(20, 40, 20);
    scene.medium.extinction = Rgb(1.0, 2.0, 4.0);
    scene.tracer.storeFluence = true;
    scene.lights.push_back(directionalLight({0.0, -1.0, 0.0}, 3.0));
    scene.render.photons = 1 << 18;
    const TraceResult result = trace(scene);
    ASSERT_FALSE(result.fluence.empty());

    const GridSpec grid = scene.grid.spec();
    double worst = 0.0;
    for (int j = 2; j < 38; j += 5) {
        double sum[3] = {0, 0, 0};
        int cells = 0;
        for (int k = 4; k < 16; ++k)
            for (int i = 4; i < 16; ++i, ++cells)
                for (int c = 0; c < 3; ++c) sum[c] += result.fluence[3 * grid.linearIndex(i, j, k) + c];
        const double depth = 0.5 - grid.cellCentre(0, j, 0).y;
        for (int c = 0; c < 3; ++c) {
            const double expected = 3.0 * std::exp(-scene.medium.extinction[c] * depth);
            worst = std::max(worst, std::abs(sum[c] / cells / expected - 1.0));
        }
    }
    reportFigure("fluence_beer_lambert_worst_relative_error", worst);
    EXPECT_LT(worst, 0.02);
}

struct CausticRun {
    std::vector<float> map;
    std::uint64_t steps = 0;
};

CausticRun sphereCaustic(TracerDesc tracer) {
    Scene scene = emptyScene(glm::dvec3(-0.5, 0.0, -0.5), glm::dvec3(0.5, 1.0, 0.5), 64);
    ObjectDesc sphere;
    sphere.sphere = {glm::dvec3(0.0, 0.6, 0.0), 0.25};
    sphere.material.index = 1.5;
    scene.objects.push_back(sphere);
    scene.lights.push_back(directionalLight({0.0, -1.0, 0.0}, 1.0));
    scene.receivers.push_back(floorReceiver(0.05, 0.5, 64));
    scene.render.photons = 1 << 18;
    scene.tracer = tracer;
    const TraceResult result = trace(scene);
    return {result.map, result.stats.steps};
}

double relativeL1(const std::vector<float>& map, const std::vector<float>& reference) {
    double difference = 0.0, total = 0.0;
    for (std::size_t i = 0; i < map.size(); ++i) {
        difference += std::abs(map[i] - reference[i]);
        total += std::abs(reference[i]);
    }
    return difference / total;
}

// The glass-sphere caustic (R = 0.25 m, n = 1.5, 64³, parallel light): the
// octree-adaptive tracer reaches the same caustic as uniform half-voxel steps
// — difference measure: relative L1 distance of the receiver irradiance map
// to a uniform quarter-voxel RK4 reference — with several times fewer steps.
TEST(TracerAccuracy, AdaptiveStepsMatchUniformWithFewerSteps) {
    TracerDesc reference;
    reference.integrator = TracerDesc::Integrator::Rk4;
    reference.stepPolicy = TracerDesc::StepPolicy::Uniform;
    reference.stepVoxels = 0.25;
    TracerDesc uniform;
    uniform.stepPolicy = TracerDesc::StepPolicy::Uniform;
    uniform.stepVoxels = 0.5;
    TracerDesc adaptive;  // defaults: leapfrog, octree, Δs_min = 0.5 voxel
    const CausticRun truth = sphereCaustic(reference);
    const CausticRun uniformRun = sphereCaustic(uniform);
    const CausticRun adaptiveRun = sphereCaustic(adaptive);
    const double uniformError = relativeL1(uniformRun.map, truth.map);
    const double adaptiveError = relativeL1(adaptiveRun.map, truth.map);
    const double stepRatio = static_cast<double>(uniformRun.steps) / static_cast<double>(adaptiveRun.steps);
    reportFigure("caustic_l1_uniform_half_voxel", uniformError);
    reportFigure("caustic_l1_octree", adaptiveError);
    reportFigure("caustic_steps_uniform_over_octree", stepRatio);
    EXPECT_GT(stepRatio, 3.0);
    EXPECT_LT(adaptiveError, 1.5 * uniformError + 0.01);
}

// A spot light sends its power into its cone: with the cone wholly inside a
// receiver below it, the receiver gets the light's power (to 0.5%), and
// nothing lands outside the cone's footprint.
TEST(TracerAccuracy, SpotLightPutsItsPowerInsideItsCone) {
    Scene scene = emptyScene(glm::dvec3(-0.6, -0.1, -0.6), glm::dvec3(0.6, 1.1, 0.6), 16);
    LightDesc spot;
    spot.kind = LightDesc::Kind::Spot;
    spot.position = glm::dvec3(0.0, 1.0, 0.0);
    spot.direction = glm::dvec3(0.0, -1.0, 0.0);
    spot.power = Rgb(2.0, 1.0, 0.5);
    spot.coneAngleDeg = 20.0;
    spot.falloffDeg = 8.0;
    scene.lights.push_back(spot);
    scene.receivers.push_back(floorReceiver(0.0, 1.2, 48));
    scene.render.photons = 1 << 18;
    const TraceResult result = trace(scene);
    reportFigure("spot_received_over_power", result.stats.received.r / 2.0);
    EXPECT_NEAR(result.stats.received.r / 2.0, 1.0, 0.005);
    EXPECT_NEAR(result.stats.received.b / 0.5, 1.0, 0.005);
    const double footprint = std::tan(20.0 * std::numbers::pi / 180.0) + 2.0 * 1.2 / 48;  // cone radius + filter
    for (int j = 0; j < 48; ++j)
        for (int i = 0; i < 48; ++i) {
            const double r = std::hypot((i + 0.5) / 48 * 1.2 - 0.6, (j + 0.5) / 48 * 1.2 - 0.6);
            if (r > footprint) {
                EXPECT_EQ(result.map[static_cast<std::size_t>(3 * (48 * j + i))], 0.0f);
            }
        }
}

// Dispersion: with a larger index scale for blue than red, a glass sphere
// focuses blue nearer than red, so on a floor below the red focus the blue
// caustic is the wider one — and each channel keeps its power.
TEST(TracerAccuracy, DispersionSeparatesColours) {
    Scene scene = emptyScene(glm::dvec3(-0.5, 0.0, -0.5), glm::dvec3(0.5, 1.0, 0.5), 48);
    ObjectDesc sphere;
    sphere.sphere = {glm::dvec3(0.0, 0.7, 0.0), 0.25};
    sphere.material.index = 1.5;
    scene.objects.push_back(sphere);
    scene.lights.push_back(directionalLight({0.0, -1.0, 0.0}, 1.0));
    scene.receivers.push_back(floorReceiver(0.25, 0.4, 64));
    scene.tracer.dispersion = Rgb(0.9, 1.0, 1.15);
    scene.render.photons = 3 << 16;
    const TraceResult result = trace(scene);
    // Second moment of each channel's irradiance about the axis.
    double spread[3] = {0, 0, 0}, total[3] = {0, 0, 0};
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i) {
            const double r2 = std::pow((i + 0.5) / 64 * 0.4 - 0.2, 2) + std::pow((j + 0.5) / 64 * 0.4 - 0.2, 2);
            if (r2 > 0.08 * 0.08) continue;
            for (int c = 0; c < 3; ++c) {
                const double e = result.map[static_cast<std::size_t>(3 * (64 * j + i) + c)];
                spread[c] += e * r2;
                total[c] += e;
            }
        }
    const double redRadius = std::sqrt(spread[0] / total[0]), blueRadius = std::sqrt(spread[2] / total[2]);
    reportFigure("dispersion_blue_over_red_caustic_radius", blueRadius / redRadius);
    EXPECT_GT(blueRadius, 1.1 * redRadius);
    EXPECT_NEAR(result.stats.emitted.r / result.stats.emitted.b, 1.0, 0.01) << "each channel keeps its power";
}


// View factor from a small patch to a parallel a × b rectangle with one
// corner straight below it at distance c (Howell's catalogue, B-3).
double cornerViewFactor(double a, double b, double c) {
    const double x = a / c, y = b / c;
    return (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
            y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y))) /
           (2.0 * std::numbers::pi);
}

// A bouncing floor of albedo ρ under a vertical beam E0 is a Lambertian
// emitter of radiance ρE0/π; a small downward-facing receiver at height h
// above its centre then sees E = ρ·E0·(F_floor − F_shadow), with F the view
// factors of the floor square and of the receiver's own shadow (within 3%).
TEST(TracerAccuracy, BouncingFloorLightsACeilingByItsViewFactor) {
    Scene scene = emptyScene(glm::dvec3(-1.0, -0.1, -1.0), glm::dvec3(1.0, 0.6, 1.0), 8);
    scene.lights.push_back(directionalLight({0.0, -1.0, 0.0}, 2.0));
    ReceiverDesc ceiling = floorReceiver(0.5, 0.1, 4);
    ceiling.normal = glm::dvec3(0.0, -1.0, 0.0);
    scene.receivers.push_back(ceiling);
    ReceiverDesc floor = floorReceiver(0.0, 2.0, 16);
    floor.albedo = Rgb(0.5, 0.7, 0.9);
    floor.bounce = true;
    scene.receivers.push_back(floor);
    scene.render.photons = 1 << 22;
    const TraceResult result = trace(scene);

    const double floorFactor = 4.0 * cornerViewFactor(1.0, 1.0, 0.5);
    const double shadowFactor = 4.0 * cornerViewFactor(0.05, 0.05, 0.5);
    for (int c = 0; c < 3; ++c) {
        const double expected = floor.albedo[c] * 2.0 * (floorFactor - shadowFactor);
        const double measured = channelMean(result.map, c);
        reportFigure(("bounce_ceiling_over_view_factor_channel_" + std::to_string(c)).c_str(), measured / expected);
        EXPECT_NEAR(measured / expected, 1.0, 0.03) << "channel " << c;
    }
    EXPECT_GT(result.stats.reflected.g, 0.0);
    EXPECT_LT(result.stats.balanceError(), 1e-6);
}

}  // namespace
}  // namespace eikon
