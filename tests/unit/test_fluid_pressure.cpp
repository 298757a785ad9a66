// Pressure projection and its multigrid-preconditioned CG ([McAdams10]).
#include "sim/fluid/PressureSolver.h"

#include "sim/fluid/ParallelOps.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace eikon::sim {
namespace {

using Boundary = SimDesc::Boundary;

std::array<Boundary, 6> allClosed() { return {}; }

double maxRelativeDivergence(const MacGrid& mac, const FluidDomain& domain) {
    double maxDiv = 0.0;
    const glm::ivec3 n = mac.grid.resolution;
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i)
                if (!domain.isSolid(i, j, k)) maxDiv = std::max(maxDiv, std::abs(mac.divergence(i, j, k)));
    double maxU = 0.0;
    for (const GridField& u : mac.velocity) maxU = std::max(maxU, maxAbs(u.values));
    return maxDiv * mac.h.x / maxU;
}

// Two unit cells between open x faces, closed elsewhere, with u = 1 on the
// middle face only. By hand (p in units of Δt/ρ·pressure, h = 1):
//   cell 0: p0 (open face, p = 0 outside) + (p0 − p1) = −∇·u = −1
//   cell 1: (p1 − p0) + p1                          = +1
// so p = (−1/3, 1/3) and u − ∇p = 1/3 on all three x faces: a uniform flow.
TEST(FluidPressure, TwoCellSolveMatchesHandComputedAnswer) {
    const GridSpec grid{glm::ivec3(2, 1, 1), glm::dvec3(0.0), glm::dvec3(2.0, 1.0, 1.0)};
    std::array<Boundary, 6> faces = allClosed();
    faces[0] = faces[1] = Boundary::Open;
    const FluidDomain domain(grid.resolution, faces);
    MacGrid mac(grid);
    mac.velocity[0](1, 0, 0) = 1.0;
    GridField pressure = mac.cellField(0.0);
    const PressureSolver solver(domain, mac.h);
    const SolveStats stats = solver.project(mac, pressure, 1e-12, 10);
    EXPECT_LE(stats.relativeResidual, 1e-12);
    EXPECT_NEAR(pressure(0, 0, 0), -1.0 / 3.0, 1e-12);
    EXPECT_NEAR(pressure(1, 0, 0), 1.0 / 3.0, 1e-12);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(mac.velocity[0](i, 0, 0), 1.0 / 3.0, 1e-12) << "face " << i;
}

// A closed 2×2×1 box of half-metre cells with u = 1 on the face between the
// two lower cells. With w = 1/h² = 4 and, by symmetry, p00 = −p10 = a,
// p01 = −p11 = b, the equations Σ w (p_c − p_n) = −∇·u read
//   cell (0,0): w(2a) + w(a − b) = −2   →  12a − 4b = −2
//   cell (0,1): w(2b) + w(b − a) =  0   →  a = 3b
// so b = −1/16, a = −3/16, and u − ∇p is the divergence-free part: a loop of
// 1/4 m/s around the box (1 − 2·(3/8) on the lower face, −2·(1/8) on the upper).
TEST(FluidPressure, ClosedFourCellBoxMatchesHandComputedAnswer) {
    const GridSpec grid{glm::ivec3(2, 2, 1), glm::dvec3(0.0), glm::dvec3(1.0, 1.0, 0.5)};
    const FluidDomain domain(grid.resolution, allClosed());
    MacGrid mac(grid);
    mac.velocity[0](1, 0, 0) = 1.0;
    GridField pressure = mac.cellField(0.0);
    const PressureSolver solver(domain, mac.h);
    solver.project(mac, pressure, 1e-12, 20);
    EXPECT_NEAR(pressure(0, 0, 0), -3.0 / 16.0, 1e-12);
    EXPECT_NEAR(pressure(1, 0, 0), 3.0 / 16.0, 1e-12);
    EXPECT_NEAR(pressure(0, 1, 0), -1.0 / 16.0, 1e-12);
    EXPECT_NEAR(pressure(1, 1, 0), 1.0 / 16.0, 1e-12);
    EXPECT_NEAR(mac.velocity[0](1, 0, 0), 0.25, 1e-12);
    EXPECT_NEAR(mac.velocity[0](1, 1, 0), -0.25, 1e-12);
    EXPECT_NEAR(mac.velocity[1](0, 1, 0), -0.25, 1e-12);
    EXPECT_NEAR(mac.velocity[1](1, 1, 0), 0.25, 1e-12);
}

// CG needs a symmetric preconditioner: x·M(y) = y·M(x) for the V-cycle,
// here on a grid with solids, one open face and uneven sizes (semi-coarsening).
TEST(FluidPressure, MultigridVCycleIsSymmetricAndPositive) {
    const glm::ivec3 n(20, 13, 9);
    std::vector<std::uint8_t> active(static_cast<std::size_t>(n.x) * n.y * n.z, 1);
    for (int k = 2; k < 6; ++k)
        for (int j = 3; j < 8; ++j) active[5 + n.x * (j + n.y * k)] = 0;
    const bool open[6] = {false, false, false, true, false, false};
    const MultigridPreconditioner mg(n, glm::dvec3(0.1, 0.1, 0.12), active, open);
    EXPECT_GE(mg.levelCount(), 3);
    std::mt19937 rng(7);
    std::normal_distribution<double> normal;
    std::vector<double> x(active.size()), y(active.size()), mx, my;
    for (std::size_t c = 0; c < x.size(); ++c) {
        x[c] = active[c] ? normal(rng) : 0.0;
        y[c] = active[c] ? normal(rng) : 0.0;
    }
    mg.apply(x, mx);
    mg.apply(y, my);
    const double xMy = dot(x, my);
    EXPECT_NEAR(xMy, dot(y, mx), 1e-10 * std::abs(xMy));
    EXPECT_GT(dot(x, mx), 0.0);
}

// A 32³ closed box with a sphere obstacle and a random velocity field:
// projection reaches max|∇·u|·h/max|u| < 1e-6 (tolerance 1e-8), and the
// V-cycle preconditioner keeps CG under 25 iterations (plain CG needs ~100+).
TEST(FluidPressure, MultigridPcgProjectsARandomFieldAroundAnObstacle) {
    const GridSpec grid{glm::ivec3(32), glm::dvec3(0.0), glm::dvec3(1.0)};
    FluidDomain domain(grid.resolution, allClosed());
    MacGrid mac(grid);
    SimDesc::Obstacle ball;
    ball.kind = SimDesc::Obstacle::Kind::Sphere;
    ball.sphere = {glm::dvec3(0.5, 0.4, 0.5), 0.2};
    addObstacles(domain, mac, {ball});
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    for (GridField& u : mac.velocity)
        for (double& v : u.values) v = uniform(rng);
    enforceVelocityBoundaries(mac, domain);
    GridField pressure = mac.cellField(0.0);
    const PressureSolver solver(domain, mac.h);
    const SolveStats stats = solver.project(mac, pressure, 1e-8, 200);
    EXPECT_LE(stats.relativeResidual, 1e-8);
    EXPECT_LT(stats.iterations, 25);
    EXPECT_LT(maxRelativeDivergence(mac, domain), 1e-6);
}

}  // namespace
}  // namespace eikon::sim
