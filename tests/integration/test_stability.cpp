// Stability suite, GPU tracer: stiff and extreme inputs. Each case asserts no
// NaN or Inf (receiver maps and fluence are checked by traceFields, figures
// here), termination (every photon ends escaped, received, cut off or
// blocked), bounded energy (emitted = absorbed + escaped + received + cut off
// + blocked to 1e-6) and a stated error bound.
#include "verify/reference/AnalyticFields.h"
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace eikon {
namespace {

using namespace test;

void expectSound(const render::PhotonStats& s, long long photons, unsigned maxSteps, const std::string& name) {
    EXPECT_EQ(static_cast<long long>(s.photonsEscaped + s.photonsReceived + s.photonsCutOff + s.photonsBlocked), photons)
        << name << ": every photon terminates";
    EXPECT_LE(s.steps, static_cast<std::uint64_t>(photons) * maxSteps) << name;
    EXPECT_LT(s.balanceError(), 1e-6) << name;
    for (const Rgb& power : {s.emitted, s.absorbed, s.escaped, s.received, s.cutOff, s.blocked})
        for (int c = 0; c < 3; ++c) EXPECT_TRUE(std::isfinite(power[c]) && power[c] >= 0.0) << name;
    EXPECT_TRUE(std::isfinite(s.maxInvariantError) && std::isfinite(s.meanInvariantError)) << name;
}

// Sound, and nearly all power delivered (received or escaped, none lost to
// the step cap) with the mean |v| = n violation under `meanInvariantBound`.
void expectDelivered(const TraceResult& result, long long photons, const std::string& name, double meanInvariantBound) {
    expectSound(result.stats, photons, 4 * 96 * 2, name);
    const double delivered = (result.stats.received.r + result.stats.escaped.r) / result.stats.emitted.r;
    reportFigure((name + "_delivered_fraction").c_str(), delivered);
    reportFigure((name + "_max_invariant_error").c_str(), result.stats.maxInvariantError);
    reportFigure((name + "_mean_invariant_error").c_str(), result.stats.meanInvariantError);
    EXPECT_GT(delivered, 0.99) << name;
    EXPECT_LT(result.stats.meanInvariantError, meanInvariantBound) << name;
}

LightDesc pencil(glm::dvec3 position, glm::dvec3 direction) {
    LightDesc light;
    light.kind = LightDesc::Kind::Spot;
    light.position = position;
    light.direction = glm::normalize(direction);
    light.power = Rgb(1.0);
    light.coneAngleDeg = 1e-6;  // parallel in float32
    light.falloffDeg = 0.0;
    return light;
}

// The recorded vertices of photon p (w = 1), in order.
std::vector<glm::dvec3> pathOf(const TraceResult& result, int photon, int capacity) {
    std::vector<glm::dvec3> path;
    for (int v = 0; v < capacity; ++v) {
        const glm::vec4 x = result.paths[static_cast<std::size_t>(photon * capacity + v)];
        if (x.w != 1.0f) break;
        path.emplace_back(x);
    }
    return path;
}

// A diamond sphere (n = 2.42) with no smoothing at all: the index jumps by
// 1.42 between neighbouring voxels. Bound: at least 99% of the power reaches
// the floor or escapes (what is cut off is trapped light); |v| = n kept to
// 15% on average over all steps (measured 0.10: steps across the jump break
// it by up to ~1, the largest value, which is reported).
TEST(Stability, SharpDiamondInterfaceWithoutSmoothing) {
    Scene scene = emptyScene(glm::dvec3(-0.5), glm::dvec3(0.5), 32);
    scene.grid.smoothingSigmaVoxels = 0.0;
    ObjectDesc diamond;
    diamond.sphere = {glm::dvec3(0.0, 0.1, 0.0), 0.3};
    diamond.material.index = 2.42;
    scene.objects.push_back(diamond);
    scene.lights.push_back(directionalLight({0.1, -1.0, 0.0}, 1.0));
    scene.receivers.push_back(floorReceiver(-0.45, 1.0, 32));
    scene.render.photons = 1 << 14;
    for (auto integrator : kIntegrators) {
        scene.tracer.integrator = integrator;
        const TraceResult result = trace(scene);
        expectDelivered(result, scene.render.photons,
                        std::string("diamond_") + kIntegratorNames[static_cast<int>(integrator)], 0.15);
    }
}

// Grazing incidence: a glass surface (n = 1.5) graded linearly over 4 voxels
// (1 cm voxels, no smoothing: trilinear sampling of cell-centred values is
// then exact inside the ramp); a pencil beam launched in the ramp at
// n0 = 1.125 travelling at 89.9° from the surface normal. v·x̂ = n·sinθ is
// invariant (the field varies in y only), so deep in the glass the ray runs
// at asin(n0·sin 89.9° / 1.5) from the normal. Bound: 0.05°.
TEST(Stability, GrazingIncidenceRefractsBySnell) {
    const double h = 0.01, rampBottom = 0.155, rampTop = 0.195;  // cell centres at (j + ½)·h
    Scene scene = emptyScene(glm::dvec3(0.0), glm::dvec3(2.0, 0.32, 0.04), 1);
    scene.grid.resolution = glm::ivec3(200, 32, 4);
    scene.grid.smoothingSigmaVoxels = 0.0;
    const double incidence = 89.9 * std::numbers::pi / 180.0;
    const double launchY = rampTop - 0.25 * (rampTop - rampBottom);
    scene.lights.push_back(pencil({0.05, launchY, 0.02}, {std::sin(incidence), -std::cos(incidence), 0.0}));
    scene.tracer.stepPolicy = TracerDesc::StepPolicy::Uniform;
    scene.tracer.stepVoxels = 0.25;
    scene.render.photons = 64;
    FieldSet fields;
    fields.grid = scene.grid.spec();
    fields.deltaIndex.resize(fields.grid.cellCount());
    auto glassOffset = [&](double y) { return 0.5 * std::clamp((rampTop - y) / (rampTop - rampBottom), 0.0, 1.0); };
    for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 32; ++j)
            for (int i = 0; i < 200; ++i)
                fields.deltaIndex[fields.grid.linearIndex(i, j, k)] = static_cast<float>(glassOffset((j + 0.5) * h));
    fields.indexVersion = 1;
    const TraceResult result = traceFields(scene, fields, {.recordPathVertices = 4000, .recordedPhotons = 64});
    expectSound(result.stats, 64, render::defaultMaxSteps(fields.grid, 0.25 * h), "grazing");
    const double n0 = 1.0 + glassOffset(launchY);
    const double expected = std::asin(n0 * std::sin(incidence) / 1.5) * 180.0 / std::numbers::pi;
    double worst = 0.0;
    int refracted = 0;
    for (int p = 0; p < 64; ++p) {
        const auto path = pathOf(result, p, 4000);
        for (std::size_t v = 1; v < path.size(); ++v)
            if (path[v - 1].y < rampBottom - 3 * h && path[v].y > 2 * h) {
                const glm::dvec3 d = glm::normalize(path[v] - path[v - 1]);
                worst = std::max(worst, std::abs(std::atan2(d.x, -d.y) * 180.0 / std::numbers::pi - expected));
                ++refracted;
            }
    }
    reportFigure("grazing_refraction_angle_error_deg", worst);
    reportFigure("grazing_max_invariant_error", result.stats.maxInvariantError);
    EXPECT_GE(refracted, 64) << "every photon crosses into the glass";
    EXPECT_LT(worst, 0.05);
}

// Whispering gallery: in Maxwell's fish-eye n = 2/(1 + (r/0.5)²) every ray is
// a circle, so light from P = (0.3, 0, 0) whose circle fits in the grid is
// trapped for ever. It must end at the step cap (cut off) with its power
// counted. Bound: trapped light is ≥ 10% of the power, the balance holds to
// 1e-6, and leapfrog keeps |v| = n to 2% on average over up to 3000 steps per
// photon (measured 1.2%; the largest, 0.2, is near the grid's faces, where
// the sampled field is clamped).
TEST(Stability, WhisperingGalleryPhotonsTerminateWithPowerAccounted) {
    Scene scene = emptyScene(glm::dvec3(-1.0), glm::dvec3(1.0), 32);
    scene.grid.smoothingSigmaVoxels = 0.0;
    LightDesc light;
    light.position = glm::dvec3(0.3, 0.0, 0.0);
    light.power = Rgb(1.0);
    scene.lights.push_back(light);
    scene.tracer.stepPolicy = TracerDesc::StepPolicy::Uniform;
    scene.tracer.maxSteps = 3000;
    scene.render.photons = 1 << 12;
    const reference::FishEyeField fishEye(2.0, 0.5);
    FieldSet fields;
    fields.grid = scene.grid.spec();
    fields.deltaIndex.resize(fields.grid.cellCount());
    for (int k = 0; k < 32; ++k)
        for (int j = 0; j < 32; ++j)
            for (int i = 0; i < 32; ++i)
                fields.deltaIndex[fields.grid.linearIndex(i, j, k)] =
                    static_cast<float>(fishEye.index(fields.grid.cellCentre(i, j, k)) - 1.0);
    fields.indexVersion = 1;
    const TraceResult result = traceFields(scene, fields);
    expectSound(result.stats, scene.render.photons, 3000, "whispering gallery");
    const double trapped = result.stats.cutOff.r / result.stats.emitted.r;
    reportFigure("whispering_gallery_trapped_fraction", trapped);
    reportFigure("whispering_gallery_max_invariant_error", result.stats.maxInvariantError);
    reportFigure("whispering_gallery_mean_invariant_error", result.stats.meanInvariantError);
    EXPECT_GT(trapped, 0.1);
    EXPECT_GT(result.stats.photonsCutOff, 0u);
    EXPECT_LT(result.stats.meanInvariantError, 0.02);
}

// Extinction 0 and 10⁶ per metre (a 1/κ of 1 µm under 3 cm voxels): with
// none, nothing is absorbed and all power reaches the floor or escapes; with
// 10⁶, everything entering the medium is absorbed (received < 1e-6 of emitted).
TEST(Stability, ExtinctionZeroAndOneMillionPerMetre) {
    for (double kappa : {0.0, 1e6}) {
        Scene scene = emptyScene(glm::dvec3(-0.5), glm::dvec3(0.5), 32);
        ObjectDesc slab;
        slab.kind = ObjectDesc::Kind::Box;
        slab.box = {glm::dvec3(-0.6, -0.2, -0.6), glm::dvec3(0.6, 0.2, 0.6)};
        slab.material.extinction = Rgb(kappa);
        scene.objects.push_back(slab);
        scene.lights.push_back(directionalLight({0.0, -1.0, 0.0}, 1.0));
        scene.receivers.push_back(floorReceiver(-0.45, 0.8, 16));
        scene.render.photons = 1 << 14;
        const TraceResult result = trace(scene);
        const std::string name = "extinction_" + std::to_string(kappa);
        expectSound(result.stats, scene.render.photons, 4 * 96 * 2, name);
        if (kappa == 0.0) {
            EXPECT_EQ(result.stats.absorbed.r, 0.0) << name;
            EXPECT_NEAR(result.stats.received.r + result.stats.escaped.r, result.stats.emitted.r,
                        1e-6 * result.stats.emitted.r);
        } else {
            EXPECT_LT(result.stats.received.r, 1e-6 * result.stats.emitted.r) << name;
            EXPECT_GT(result.stats.absorbed.r, 0.5 * result.stats.emitted.r) << name;
        }
    }
}

// Index range 1 to 4: a sphere of n = 4 in air, and a bubble of n = 1 in a
// medium of n = 4 (default 1.5-voxel smoothing). Bound: ≥ 99% of the power
// delivered (floor or escaped), |v| = n kept to 3% on average over all steps.
TEST(Stability, IndexRangeOneToFour) {
    for (double medium : {1.0, 4.0}) {
        Scene scene = emptyScene(glm::dvec3(-0.5), glm::dvec3(0.5), 32);
        scene.medium.index = medium;
        ObjectDesc sphere;
        sphere.sphere = {glm::dvec3(0.0, 0.1, 0.0), 0.3};
        sphere.material.index = 5.0 - medium;
        scene.objects.push_back(sphere);
        scene.lights.push_back(directionalLight({0.0, -1.0, 0.05}, 1.0));
        scene.receivers.push_back(floorReceiver(-0.45, 1.0, 32));
        scene.render.photons = 1 << 14;
        const TraceResult result = trace(scene);
        expectDelivered(result, scene.render.photons, "index_medium_" + std::to_string(static_cast<int>(medium)), 0.03);
    }
}

// Tiny gradients, the float32 δn precision case: air (n_ref = 1.000293) with
// Δn = 1e-6 across 1 m of height (δn = 1e-6·(y − 0.5)), a horizontal pencil
// beam over 100 m. In n = n0 + g·y it rises by (C/g)(cosh(g·x/C) − 1) ≈ 5 mm
// (C = n at launch). Stored as float32 n, the whole Δn would be ~8 ulps.
// Bound: the rise within 1%.
TEST(Stability, TinyGradientOverHundredMetres) {
    const double g = 1e-6, y0 = 0.5, nRef = 1.000293;
    Scene scene = emptyScene(glm::dvec3(0.0), glm::dvec3(100.0, 1.0, 1.0), 1);
    scene.grid.resolution = glm::ivec3(800, 8, 8);
    scene.grid.smoothingSigmaVoxels = 0.0;
    scene.medium.index = nRef;
    scene.lights.push_back(pencil({0.01, y0, 0.5}, {1.0, 0.0, 0.0}));
    scene.tracer.stepPolicy = TracerDesc::StepPolicy::Uniform;
    scene.tracer.stepVoxels = 1.0;
    scene.render.photons = 16;
    FieldSet fields;
    fields.grid = scene.grid.spec();
    fields.referenceIndex = nRef;
    fields.deltaIndex.resize(fields.grid.cellCount());
    for (int k = 0; k < 8; ++k)
        for (int j = 0; j < 8; ++j)
            for (int i = 0; i < 800; ++i)
                fields.deltaIndex[fields.grid.linearIndex(i, j, k)] =
                    static_cast<float>(g * (fields.grid.cellCentre(i, j, k).y - y0));
    fields.indexVersion = 1;
    const TraceResult result = traceFields(scene, fields, {.recordPathVertices = 900, .recordedPhotons = 16});
    expectSound(result.stats, 16, render::defaultMaxSteps(fields.grid, 0.125), "tiny gradient");
    double worst = 0.0;
    for (int p = 0; p < 16; ++p) {
        const auto path = pathOf(result, p, 900);
        ASSERT_GT(path.size(), 700u);
        glm::dvec3 last = path[0];
        for (const auto& x : path)
            if (fields.grid.contains(x)) last = x;
        const double c = nRef;  // horizontal launch at y0, where δn = 0
        const double rise = c / g * (std::cosh(g * (last.x - 0.01) / c) - 1.0);
        worst = std::max(worst, std::abs((last.y - y0) / rise - 1.0));
    }
    reportFigure("tiny_gradient_rise_relative_error", worst);
    EXPECT_LT(worst, 0.01);
}

}  // namespace
}  // namespace eikon
