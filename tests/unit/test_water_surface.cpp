// The damped wave equation of the water deformer: energy bookkeeping and
// reflection at the walls, and the closed water-body mesh.
#include "sim/deform/WaterSurface.h"

#include <gtest/gtest.h>

#include <cmath>

namespace eikon::sim {
namespace {

WaterDesc swellingPool(double damping) {
    WaterDesc desc;
    desc.basinMin = glm::dvec3(-0.5, -0.3, -0.5);
    desc.basinMax = glm::dvec3(0.5, 0.0, 0.5);
    desc.cells = glm::ivec2(64, 64);
    desc.waveSpeed = 0.4;
    desc.damping = damping;
    desc.swellAmplitude = 0.004;
    desc.swellWavelength = 0.12;
    desc.swellWaves = 6;
    return desc;
}

// With damping and no input, E^{n+½} never grows, and over 2 s it falls by
// about exp(−γt) (the damping acts on the kinetic half of the energy, so
// the mean decay rate is γ: factor e^{−1} = 0.37 for γ = 0.5, t = 2 s).
TEST(WaterSurface, DampedEnergyDecaysMonotonically) {
    WaterSurface water(swellingPool(0.5));
    const double dt = water.stableStep();
    water.step(dt);
    const double first = water.energy();
    ASSERT_GT(first, 0.0);
    double previous = first;
    const int steps = static_cast<int>(2.0 / dt);
    for (int n = 0; n < steps; ++n) {
        water.step(dt);
        const double e = water.energy();
        ASSERT_LE(e, previous * (1.0 + 1e-12)) << "step " << n;
        previous = e;
    }
    EXPECT_NEAR(previous / first, std::exp(-0.5 * 2.0), 0.08);
}

// Without damping the leapfrog energy is conserved to rounding.
TEST(WaterSurface, UndampedEnergyIsConserved) {
    WaterSurface water(swellingPool(0.0));
    const double dt = water.stableStep();
    water.step(dt);
    const double first = water.energy();
    for (int n = 0; n < 500; ++n) water.step(dt);
    EXPECT_NEAR(water.energy() / first, 1.0, 1e-9);
}

// A bump at x0 = 1 m in a 4 m channel splits into two halves moving at c; the
// left one reaches the wall at x = 0 at t = 1 s and comes back upright (a
// reflecting wall, ∂h/∂x = 0): at t = 1.5 s it is at x = 0.5 m with about
// half the bump's height, while the right half is at x = 2.5 m.
TEST(WaterSurface, RippleReflectsAtTheWalls) {
    WaterDesc desc;
    desc.basinMin = glm::dvec3(0.0, -1.0, 0.0);
    desc.basinMax = glm::dvec3(4.0, 0.0, 0.04);
    desc.cells = glm::ivec2(801, 3);
    desc.waveSpeed = 1.0;
    desc.damping = 0.0;
    WaterSurface water(desc);
    const double amplitude = 0.01, sigma = 0.05;
    for (int k = 0; k < 3; ++k)
        for (int i = 0; i < 801; ++i) {
            const double x = water.nodePosition(i, k).x - 1.0;
            water.setHeight(i, k, amplitude * std::exp(-x * x / (2 * sigma * sigma)));
        }
    water.advanceTo(1.5);
    auto peakNear = [&](double x0, double& where) {
        double best = -1.0;
        for (int i = 0; i < 801; ++i) {
            const double x = water.nodePosition(i, 1).x;
            if (std::abs(x - x0) < 0.3 && water.height(i, 1) > best) {
                best = water.height(i, 1);
                where = x;
            }
        }
        return best;
    };
    double reflectedAt = 0.0, transmittedAt = 0.0;
    const double reflected = peakNear(0.5, reflectedAt);
    const double travelling = peakNear(2.5, transmittedAt);
    EXPECT_NEAR(reflectedAt, 0.5, 0.02);
    EXPECT_NEAR(transmittedAt, 2.5, 0.02);
    EXPECT_NEAR(reflected / (0.5 * amplitude), 1.0, 0.1);
    EXPECT_NEAR(reflected / travelling, 1.0, 0.05) << "the wall gives back what reached it";
    EXPECT_LT(std::abs(water.height(400, 1)), 0.02 * amplitude) << "nothing left near x = 2 between the pulses";
}

// The body is closed and holds basin volume plus the surface's displacement.
TEST(WaterSurface, BodyMeshIsClosedWithTheRightVolume) {
    WaterSurface water(swellingPool(0.1));
    water.advanceTo(0.3);
    const TriangleMesh mesh = water.mesh();
    EXPECT_TRUE(countEdges(mesh).closedManifold());
    // Trapezoidal integral of the heights over the node grid.
    double displaced = 0.0;
    for (int k = 0; k < water.nodesZ(); ++k)
        for (int i = 0; i < water.nodesX(); ++i) {
            const double wx = (i == 0 || i == water.nodesX() - 1) ? 0.5 : 1.0;
            const double wz = (k == 0 || k == water.nodesZ() - 1) ? 0.5 : 1.0;
            displaced += wx * wz * water.height(i, k) * water.spacingX() * water.spacingZ();
        }
    EXPECT_NEAR(enclosedVolume(mesh), 1.0 * 1.0 * 0.3 + displaced, 1e-3 * 0.3 * 0.004);
}

TEST(WaterSurface, DropsAndDisturbancesPutEnergyIn) {
    WaterDesc desc = swellingPool(0.0);
    desc.swellAmplitude = 0.0;
    desc.drops.push_back({0.05, glm::dvec2(0.1, 0.0), 0.003, 0.03});
    desc.disturbances.push_back({glm::dvec2(-0.3, -0.3), glm::dvec2(0.2, 0.0), 0.0, 0.5, 2.0, 0.03});
    WaterSurface water(desc);
    water.step(water.stableStep());
    EXPECT_GT(water.energy(), 0.0) << "the disturbance acts from t = 0";
    const double beforeDrop = water.energy();
    water.advanceTo(0.1);
    EXPECT_GT(water.energy(), beforeDrop);
}

}  // namespace
}  // namespace eikon::sim
