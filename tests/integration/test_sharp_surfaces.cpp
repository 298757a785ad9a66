// Sharp surfaces in the photon pass against closed forms, from recorded
// photon paths (a vertex is recorded where a step ends on a surface):
// the lateral shift through a slab, the paraxial focus of a ball lens, total
// internal reflection in a glass block, and the Fresnel split at normal
// incidence.
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <vector>

namespace eikon::test {
namespace {

ObjectDesc sharpBox(glm::dvec3 min, glm::dvec3 max, double index, bool fresnel) {
    ObjectDesc object;
    object.kind = ObjectDesc::Kind::Box;
    object.box = {min, max};
    object.material.index = index;
    object.fresnel = fresnel;
    return object;
}

// The recorded vertices of one photon, up to the first unwritten one.
std::vector<glm::dvec3> pathOf(const TraceResult& result, int photon, int perPhoton) {
    std::vector<glm::dvec3> path;
    for (int v = 0; v < perPhoton; ++v) {
        const glm::vec4& vertex = result.paths[static_cast<std::size_t>(photon * perPhoton + v)];
        if (vertex.w != 1.0f) break;
        path.emplace_back(vertex);
    }
    return path;
}

// The first vertex at height y (a face of the slab), or −1.
int vertexAtHeight(const std::vector<glm::dvec3>& path, double y) {
    for (std::size_t v = 0; v < path.size(); ++v)
        if (std::abs(path[v].y - y) < 1e-5) return static_cast<int>(v);
    return -1;
}

// A slab of thickness t and index n shifts a ray entering at θ sideways by
// t·sin(θ − θ′)/cos θ′, θ′ = asin(sin θ / n) (without Fresnel reflection).
TEST(SharpSurfaces, SlabShiftsRaysSidewaysByTheClosedForm) {
    const double theta = 40.0 * M_PI / 180.0, n = 1.5, top = 0.1, bottom = -0.1;
    Scene scene = emptyScene(glm::dvec3(-0.5), glm::dvec3(0.5), 16);
    scene.objects.push_back(sharpBox({-2.0, bottom, -2.0}, {2.0, top, 2.0}, n, false));
    const glm::dvec3 d(std::sin(theta), -std::cos(theta), 0.0);
    scene.lights.push_back(directionalLight(d, 1.0));
    scene.render.photons = 4096;
    const int recorded = 64, perPhoton = 32;
    const TraceResult result = trace(scene, {.recordPathVertices = perPhoton, .recordedPhotons = recorded, .recordStride = 61});
    const double thetaT = std::asin(std::sin(theta) / n);
    const double expected = (top - bottom) * std::sin(theta - thetaT) / std::cos(thetaT);
    int checked = 0;
    double worst = 0.0;
    for (int photon = 0; photon < recorded; ++photon) {
        const std::vector<glm::dvec3> path = pathOf(result, photon, perPhoton);
        const int in = vertexAtHeight(path, top), out = vertexAtHeight(path, bottom);
        if (in < 0 || out < 0 || out + 1 >= static_cast<int>(path.size())) continue;
        const glm::dvec3 exitDirection = glm::normalize(path[out + 1] - path[out]);
        EXPECT_NEAR(glm::dot(exitDirection, d), 1.0, 1e-6) << "a slab leaves the direction as it was";
        const glm::dvec3 offset = path[out] - path[in];
        const double shift = glm::length(offset - glm::dot(offset, d) * d);
        worst = std::max(worst, std::abs(shift / expected - 1.0));
        ++checked;
    }
    reportFigure("sharp_slab_shift_worst_relative_error", worst);
    EXPECT_GE(checked, 20);
    EXPECT_LE(worst, 1e-4);
}

// Parallel light on a ball lens of radius R focuses, paraxially, n·R/(2(n − 1))
// beyond its centre: the axis crossings of rays at height h fit
// f(h) = f₀ + a·h², and f₀ must be within 0.5%.
TEST(SharpSurfaces, BallLensFocusesAtTheParaxialFocalLength) {
    const double n = 1.5, radius = 0.2;
    Scene scene = emptyScene(glm::dvec3(-0.5), glm::dvec3(0.5), 16);
    ObjectDesc ball;
    ball.kind = ObjectDesc::Kind::Sphere;
    ball.sphere = {glm::dvec3(0.0), radius};
    ball.material.index = n;
    ball.fresnel = false;
    scene.objects.push_back(ball);
    scene.lights.push_back(directionalLight({0.0, -1.0, 0.0}, 1.0));
    scene.render.photons = 1 << 16;
    const int recorded = 8192, perPhoton = 16;
    const TraceResult result = trace(scene, {.recordPathVertices = perPhoton, .recordedPhotons = recorded, .recordStride = 7});
    // Least squares of f against (1, h²) over paraxial rays.
    double s0 = 0, s1 = 0, s2 = 0, t0 = 0, t1 = 0;
    int rays = 0;
    for (int photon = 0; photon < recorded; ++photon) {
        const std::vector<glm::dvec3> path = pathOf(result, photon, perPhoton);
        std::vector<int> onSurface;
        for (std::size_t v = 0; v < path.size(); ++v)
            if (std::abs(glm::length(path[v]) - radius) < 1e-5) onSurface.push_back(static_cast<int>(v));
        if (onSurface.size() != 2 || onSurface[1] + 1 >= static_cast<int>(path.size())) continue;
        const glm::dvec3 entry = path[onSurface[0]], exit = path[onSurface[1]];
        const double h = std::hypot(entry.x, entry.z);
        if (h > 0.3 * radius || h < 1e-3) continue;
        const glm::dvec3 d = glm::normalize(path[onSurface[1] + 1] - exit);
        // Where the exit ray comes nearest the axis (x = z = 0): along d, t = −(p·d)⊥/|d⊥|².
        const glm::dvec2 p(exit.x, exit.z), dp(d.x, d.z);
        const double t = -glm::dot(p, dp) / glm::dot(dp, dp);
        const double f = -(exit.y + t * d.y);  // distance below the centre
        const double h2 = h * h;
        s0 += 1; s1 += h2; s2 += h2 * h2; t0 += f; t1 += f * h2;
        ++rays;
    }
    ASSERT_GE(rays, 30);
    const double f0 = (t0 * s2 - t1 * s1) / (s0 * s2 - s1 * s1);
    const double paraxial = n * radius / (2.0 * (n - 1.0));
    reportFigure("sharp_ball_lens_focus_over_paraxial", f0 / paraxial);
    EXPECT_NEAR(f0 / paraxial, 1.0, 0.005);
}

// Light inside a glass block meeting its face at 60° (beyond the critical
// angle asin(1/1.5) = 41.8°) is reflected whole, in the mirror direction.
TEST(SharpSurfaces, GlassBlockReflectsTotallyAtSixtyDegrees) {
    Scene scene = emptyScene(glm::dvec3(-0.5), glm::dvec3(0.5), 16);
    scene.objects.push_back(sharpBox({-0.4, -0.4, -0.4}, {0.4, 0.0, 0.4}, 1.5, true));
    LightDesc spot;
    spot.kind = LightDesc::Kind::Spot;
    spot.position = glm::dvec3(-0.2, -0.2, 0.0);
    const double angle = 60.0 * M_PI / 180.0;
    spot.direction = glm::dvec3(std::sin(angle), std::cos(angle), 0.0);  // toward the top face y = 0
    spot.coneAngleDeg = 0.5;
    spot.falloffDeg = 0.0;
    spot.power = Rgb(1.0);
    scene.lights.push_back(spot);
    scene.render.photons = 4096;
    const int recorded = 32, perPhoton = 32;
    const TraceResult result = trace(scene, {.recordPathVertices = perPhoton, .recordedPhotons = recorded, .recordStride = 13});
    int checked = 0;
    for (int photon = 0; photon < recorded; ++photon) {
        const std::vector<glm::dvec3> path = pathOf(result, photon, perPhoton);
        const int hit = vertexAtHeight(path, 0.0);
        if (hit < 1 || hit + 1 >= static_cast<int>(path.size())) continue;
        const glm::dvec3 in = glm::normalize(path[hit] - path[hit - 1]);
        const glm::dvec3 out = glm::normalize(path[hit + 1] - path[hit]);
        EXPECT_NEAR(out.x, in.x, 1e-5);
        EXPECT_NEAR(out.y, -in.y, 1e-5);
        EXPECT_NEAR(out.z, in.z, 1e-5);
        ++checked;
    }
    EXPECT_GE(checked, 16);
    EXPECT_GE(result.stats.surfaceReflections, static_cast<std::uint64_t>(scene.render.photons)) << "every photon reflects at the top";
}

// At normal incidence on glass of n = 1.5 the reflected fraction is
// ((n − 1)/(n + 1))² = 0.04: a half-space of glass (its far face outside the
// grid) reflects that share of the photons that meet it, within 1% (the
// binomial noise of the 1.5·10⁵ photons that do is 0.5%).
TEST(SharpSurfaces, FresnelReflectsFourPercentAtNormalIncidence) {
    Scene scene = emptyScene(glm::dvec3(-0.5), glm::dvec3(0.5), 16);
    scene.objects.push_back(sharpBox({-2.0, -2.0, -2.0}, {2.0, 0.0, 2.0}, 1.5, true));
    scene.lights.push_back(directionalLight({0.0, -1.0, 0.0}, 1.0));
    scene.render.photons = 1 << 18;
    const TraceResult result = trace(scene);
    const double events = static_cast<double>(result.stats.surfaceReflections + result.stats.surfaceTransmissions);
    ASSERT_GT(events, 0.25 * static_cast<double>(scene.render.photons));  // the rest of the beam misses the grid
    const double reflected = static_cast<double>(result.stats.surfaceReflections) / events;
    reportFigure("sharp_fresnel_normal_incidence_reflected_fraction", reflected);
    EXPECT_NEAR(reflected / 0.04, 1.0, 0.01);
    EXPECT_LE(result.stats.balanceError(), 1e-6);
}

// Extreme glass in graded air: spheres of n = 4 and of diamond (2.42) in the
// hot layer over a road. The energy must balance to 1e-6 with no NaN, and
// the invariant |v| = n of the graded segments must be kept as well as with
// no sphere (the crossings reset v to the new index exactly).
TEST(SharpSurfaces, DenseSpheresInHotAirBalanceAndKeepTheInvariant) {
    auto hotRoad = [] {
        Scene scene = emptyScene(glm::dvec3(-0.5, 0.0, -0.5), glm::dvec3(0.5, 1.0, 0.5), 32);
        AirTemperatureProfile air;
        air.groundTemperature = 340.0;
        air.scaleHeight = 0.2;
        scene.airProfile = air;
        scene.medium.index = 1.000293;
        scene.lights.push_back(directionalLight({0.3, -1.0, 0.2}, 1.0));
        scene.receivers.push_back(floorReceiver(0.02, 0.9, 32));
        scene.render.photons = 1 << 16;
        return scene;
    };
    const TraceResult air = trace(hotRoad());
    reportFigure("sharp_hot_air_alone_max_invariant_error", air.stats.maxInvariantError);
    for (double n : {4.0, 2.42}) {
        Scene scene = hotRoad();
        ObjectDesc ball;
        ball.kind = ObjectDesc::Kind::Sphere;
        ball.sphere = {glm::dvec3(0.0, 0.4, 0.0), 0.2};
        ball.material.index = n;
        scene.objects.push_back(ball);
        const TraceResult result = trace(scene);
        EXPECT_LE(result.stats.balanceError(), 1e-6) << "n = " << n;
        EXPECT_TRUE(std::isfinite(result.stats.maxInvariantError));
        EXPECT_GT(result.stats.surfaceTransmissions, 0u);
        reportFigure(n > 3.0 ? "sharp_n4_in_hot_air_max_invariant_error" : "sharp_diamond_in_hot_air_max_invariant_error",
                     result.stats.maxInvariantError);
        EXPECT_LE(result.stats.maxInvariantError, 1.1 * air.stats.maxInvariantError + 1e-7) << "n = " << n;
    }
}

}  // namespace
}  // namespace eikon::test
