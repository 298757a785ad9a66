// Volume painting against its closed forms: a stroke is a Gaussian tube
// around its path, a single stamp a Gaussian blob; masks confine the paint;
// the smoke pattern turns with the stroke; an index painted below zero is
// refused naming the stroke that reaches it.
#include "bridge/core/Error.h"
#include "sim/FieldOrigins.h"
#include "sim/voxelize/AnalyticVoxelizer.h"
#include "sim/voxelize/VolumePainter.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <string>

namespace eikon::sim {
namespace {

Scene paintScene(int resolution, PaintStroke stroke) {
    Scene scene;
    scene.grid.resolution = glm::ivec3(resolution);
    scene.grid.boundsMin = glm::dvec3(-0.5);
    scene.grid.boundsMax = glm::dvec3(0.5);
    scene.paint.push_back(std::move(stroke));
    return scene;
}

PaintStroke stroke(std::vector<glm::dvec3> path, double radius, double index) {
    PaintStroke s;
    s.path = std::move(path);
    s.radius = radius;
    s.index = index;
    return s;
}

// Along the middle of a straight stroke, δn = Δn·exp(−d²/2σ²), d the distance
// to the path, σ = radius/2: to 1e-3 of Δn (stamp sum and 4σ cut-off).
TEST(VolumePainter, StrokeIsAGaussianTubeAroundItsPath) {
    constexpr double kDeltaN = 0.01, kRadius = 0.1, kSigma = kRadius / 2;
    const Scene scene = paintScene(64, stroke({{-0.4, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.4, 0.0, 0.0}}, kRadius, kDeltaN));
    const FieldSet fields = voxelizeScene(scene);
    double worst = 0.0;
    int checked = 0;
    for (int k = 0; k < 64; ++k)
        for (int j = 0; j < 64; ++j)
            for (int i = 0; i < 64; ++i) {
                const glm::dvec3 p = fields.grid.cellCentre(i, j, k);
                if (std::abs(p.x) > 0.2) continue;  // away from the ends
                const double d2 = p.y * p.y + p.z * p.z;
                const double expected = kDeltaN * std::exp(-d2 / (2 * kSigma * kSigma));
                worst = std::max(worst, std::abs(fields.deltaIndex[fields.grid.linearIndex(i, j, k)] - expected));
                ++checked;
            }
    EXPECT_GT(checked, 50000);
    EXPECT_LT(worst, 1e-3 * kDeltaN);
}

// One point stamps once: Σ δn·h³ = Δn·(2π)^{3/2}·σ³ within 1%.
TEST(VolumePainter, SingleStampCarriesTheGaussianIntegral) {
    constexpr double kDeltaN = -0.02, kRadius = 0.12, kSigma = kRadius / 2;
    const FieldSet fields = voxelizeScene(paintScene(48, stroke({{0.03, -0.02, 0.01}}, kRadius, kDeltaN)));
    double integral = 0.0;
    for (float delta : fields.deltaIndex) integral += delta * fields.grid.voxelVolume();
    const double expected = kDeltaN * std::pow(2 * std::numbers::pi, 1.5) * std::pow(kSigma, 3);
    EXPECT_NEAR(integral, expected, 0.01 * std::abs(expected));
}

TEST(VolumePainter, MasksConfinePaintInsideOrOutsideObjects) {
    for (auto where : {PaintStroke::Where::InsideObjects, PaintStroke::Where::OutsideObjects}) {
        PaintStroke s = stroke({{-0.45, 0.0, 0.0}, {0.45, 0.0, 0.0}}, 0.15, 0.0);
        s.extinction = Rgb(20.0, 10.0, 5.0);
        s.where = where;
        Scene scene = paintScene(40, s);
        ObjectDesc sphere;
        sphere.sphere = {glm::dvec3(0.0), 0.2};
        sphere.material.index = 1.5;
        scene.objects.push_back(sphere);
        const FieldSet fields = voxelizeScene(scene);
        ASSERT_TRUE(fields.hasExtinction());
        double paintedInside = 0.0, paintedOutside = 0.0;
        for (int k = 0; k < 40; ++k)
            for (int j = 0; j < 40; ++j)
                for (int i = 0; i < 40; ++i) {
                    const double c = coverage(sphere, fields.grid, i, j, k, 4);
                    const float kappa = fields.extinction[3 * fields.grid.linearIndex(i, j, k)];
                    if (c == 1.0) paintedInside += kappa;
                    if (c == 0.0) paintedOutside += kappa;
                }
        if (where == PaintStroke::Where::InsideObjects) {
            EXPECT_GT(paintedInside, 0.0);
            EXPECT_EQ(paintedOutside, 0.0);
        } else {
            EXPECT_EQ(paintedInside, 0.0);
            EXPECT_GT(paintedOutside, 0.0);
        }
    }
}

// A stroke turned by 90° about y paints the turned pattern: the smoke brush's
// noise is fixed to the brush, not to the grid.
// A stroke's Δn within its range ("any") that leaves n <= 0 is refused
// naming that stroke and the medium with the position, never a cell, and not
// the strokes that do not reach it (here one on the far side of the grid).
TEST(VolumePainter, AnIndexPaintedBelowZeroNamesTheStrokeThatReachesIt) {
    Scene scene = paintScene(32, stroke({{0.3, 0.0, 0.0}}, 0.05, 0.01));
    scene.paint.insert(scene.paint.begin(), stroke({{-0.3, 0.0, 0.0}}, 0.1, -5.0));
    scene.sourcePath = "painted.json";
    const FieldSet fields = voxelizeScene(scene);
    try {
        validateFields(fields, sceneFieldOrigin(scene));
        FAIL() << "n <= 0 accepted";
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_EQ(message.rfind("painted.json: paint[0].index, medium.index (the refractive index at (", 0), 0u)
            << message;
        EXPECT_EQ(message.find("paint[1]"), std::string::npos) << message;
    }
    EXPECT_TRUE(strokeReaches(scene.paint[0], glm::dvec3(-0.3, 0.19, 0.0)));
    EXPECT_FALSE(strokeReaches(scene.paint[0], glm::dvec3(-0.3, 0.21, 0.0))) << "past the cut-off at 4σ = 2·radius";
}

TEST(VolumePainter, SmokePatternTurnsWithTheStroke) {
    constexpr int n = 32;
    PaintStroke alongX = stroke({{-0.3, 0.1, 0.05}, {0.3, 0.1, 0.05}}, 0.15, 0.01);
    alongX.brush = PaintStroke::Brush::Smoke;
    PaintStroke turned = alongX;  // R_y(90°): (x, y, z) → (z, y, −x)
    for (auto& p : turned.path) p = glm::dvec3(p.z, p.y, -p.x);
    const FieldSet a = voxelizeScene(paintScene(n, alongX));
    const FieldSet b = voxelizeScene(paintScene(n, turned));
    PaintStroke soft = alongX;
    soft.brush = PaintStroke::Brush::Soft;
    const FieldSet plain = voxelizeScene(paintScene(n, soft));
    double worst = 0.0, modulation = 0.0;
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const float valueA = a.deltaIndex[a.grid.linearIndex(i, j, k)];
                worst = std::max(worst, double(std::abs(valueA - b.deltaIndex[b.grid.linearIndex(k, j, n - 1 - i)])));
                modulation = std::max(modulation, double(std::abs(valueA - 0.5f * plain.deltaIndex[a.grid.linearIndex(i, j, k)])));
            }
    EXPECT_LT(worst, 1e-7);
    EXPECT_GT(modulation, 1e-3);  // the pattern is not a plain Gaussian
}

TEST(VolumePainter, SmokePatternStaysInUnitRange) {
    for (int s = 0; s < 2000; ++s) {
        const glm::dvec3 x(std::sin(s * 1.3) * 5.0, std::cos(s * 0.7) * 5.0, s * 0.01 - 10.0);
        const double value = smokePattern(x, 7u);
        ASSERT_GE(value, 0.0);
        ASSERT_LE(value, 1.0);
    }
}

}  // namespace
}  // namespace eikon::sim
