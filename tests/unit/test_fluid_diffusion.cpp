// Backward-Euler diffusion against its closed form, through both of its
// solvers: red–black Gauss–Seidel for small Δt·D/h², CG for large.
#include "sim/fluid/Diffusion.h"
#include "sim/fluid/GaussSeidelIteration.h"
#include "sim/fluid/ParallelOps.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace eikon::sim {
namespace {

// A cosine mode cos(πk(i + ½)/n) along x on a Neumann lattice is an
// eigenvector of the seven-point Laplacian with eigenvalue
// λ = (2 − 2cos(πk/n)) / h², so one backward-Euler step scales it by exactly
// 1 / (1 + Δt·D·λ). Checked to 1e-10 at Δt·D/h² = 0.01 (Gauss–Seidel, Jacobi
// would contract by 0.057 per sweep) and at 10 (CG).
void expectModeDecay(double dtTimesDOverH2) {
    const glm::ivec3 n(16, 3, 2);
    const double h = 0.1;
    const int k = 3;
    GridField field(n, glm::dvec3(0.5));
    for (int kk = 0; kk < n.z; ++kk)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) field(i, j, kk) = std::cos(std::numbers::pi * k * (i + 0.5) / n.x);
    const GridField start = field;
    ImplicitDiffusion diffusion(n, std::vector<DiffusionRole>(field.count(), DiffusionRole::Free));
    const double dtTimesD = dtTimesDOverH2 * h * h;
    const SolveStats stats = diffusion.diffuse(field, glm::dvec3(h), dtTimesD, 1e-13, 10000);
    EXPECT_GT(stats.iterations, 0);
    EXPECT_LE(stats.relativeResidual, 1e-13);
    const double lambda = (2.0 - 2.0 * std::cos(std::numbers::pi * k / n.x)) / (h * h);
    const double factor = 1.0 / (1.0 + dtTimesD * lambda);
    for (std::size_t c = 0; c < field.count(); ++c) EXPECT_NEAR(field.values[c], factor * start.values[c], 1e-10);
}

TEST(FluidDiffusion, CosineModeDecaysExactlyForSmallSteps) { expectModeDecay(0.01); }

TEST(FluidDiffusion, CosineModeDecaysExactlyForStiffSteps) { expectModeDecay(10.0); }

// Gauss–Seidel and CG solve the same diagonally dominant system to the same
// answer, with solid cells (diag 0) left at zero, and the residual
// Gauss–Seidel reports bounds that of the x it returns.
TEST(FluidDiffusion, GaussSeidelMatchesConjugateGradients) {
    SevenPointOperator a;
    a.size = glm::ivec3(12, 10, 8);
    const glm::dvec3 weight(0.05, 0.08, 0.03);
    const std::size_t count = static_cast<std::size_t>(a.size.x) * a.size.y * a.size.z;
    a.identity = 1.0;
    a.diagonalClass.assign(count, SevenPointOperator::kNotUnknown);
    a.coupled.assign(count, 0);
    std::vector<double> diagonal(count, 0.0);  // 1 + Σ w, summed here
    auto solid = [](int i, int j, int k) { return i == 4 && j >= 2 && j < 5 && k >= 1; };
    for (int k = 0; k < a.size.z; ++k)
        for (int j = 0; j < a.size.y; ++j)
            for (int i = 0; i < a.size.x; ++i) {
                if (solid(i, j, k)) continue;
                const std::size_t c = a.index(i, j, k);
                a.diagonalClass[c] = 0;
                diagonal[c] = 1.0;
                const glm::ivec3 cell(i, j, k);
                for (int axis = 0; axis < 3; ++axis)
                    for (int side = 0; side < 2; ++side) {
                        glm::ivec3 m = cell;
                        m[axis] += side == 0 ? -1 : 1;
                        if (m[axis] < 0 || m[axis] >= a.size[axis] || solid(m.x, m.y, m.z)) continue;
                        a.diagonalClass[c] |= SevenPointOperator::bit(axis, side);
                        a.coupled[c] |= SevenPointOperator::bit(axis, side);
                        diagonal[c] += weight[axis];
                    }
            }
    a.setWeight(weight);
    for (std::size_t c = 0; c < count; ++c) {
        ASSERT_DOUBLE_EQ(a.diagonal(c), diagonal[c]);
        ASSERT_EQ(a.inverseDiagonal(c), diagonal[c] != 0.0 ? 1.0 / diagonal[c] : 0.0);
    }
    std::mt19937 rng(3);
    std::normal_distribution<double> normal;
    std::vector<double> b(count);
    for (std::size_t c = 0; c < count; ++c) b[c] = a.isUnknown(c) ? normal(rng) : 0.0;
    std::vector<double> byGaussSeidel(count, 7.0), byCg(count, 0.0), residual(count);
    CgWorkspace work;
    const SolveStats gaussSeidel = redBlackGaussSeidel(a, b, byGaussSeidel, 1e-12, 1000);
    // The same with the rows in the bulk taken without per-cell branches.
    SevenPointOperator plain = a;
    plain.classifyRows();
    ASSERT_GT(std::count(plain.plainRow.begin(), plain.plainRow.end(), 1), 10);
    std::vector<double> byPlainRows(count, 0.0);
    const SolveStats plainStats = redBlackGaussSeidel(plain, b, byPlainRows, 1e-12, 1000);
    EXPECT_EQ(byPlainRows, byGaussSeidel);
    EXPECT_EQ(plainStats.iterations, gaussSeidel.iterations);
    const SolveStats cg = conjugateGradient(a, b, byCg, jacobiPreconditioner(a), 1e-12, 1000, false, work);
    EXPECT_LE(gaussSeidel.relativeResidual, 1e-12);
    EXPECT_LE(cg.relativeResidual, 1e-12);
    a.residual(b, byGaussSeidel, residual);
    EXPECT_LE(maxAbs(residual), gaussSeidel.relativeResidual * maxAbs(b));
    for (std::size_t c = 0; c < count; ++c) {
        EXPECT_NEAR(byGaussSeidel[c], byCg[c], 1e-11);
        if (!a.isUnknown(c)) {
            EXPECT_EQ(byGaussSeidel[c], 0.0);  // whatever x held before
        }
    }
}

}  // namespace
}  // namespace eikon::sim
