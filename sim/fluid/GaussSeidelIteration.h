// Red–black Gauss–Seidel iteration ([Saad03] §4.1, with the red–black
// ordering of §12.4.1) for a seven-point operator: each sweep updates the
// cells with (i + j + k) even from their neighbours, then the others from
// the new values,
//   x_c ← x_c + (b − A x)_c / diag_c,
// in one pass over memory (WavefrontSlices.h). For a diagonally dominant A
// such as the backward-Euler diffusion matrix I + Δt·D·L, Jacobi contracts
// the error by ρ = max_c Σ_n w / diag_c per sweep and this ordering by about
// ρ² ([Saad03] §4.2.4, consistently ordered matrices): half the sweeps, and
// no second vector. A sweep reads and writes a quarter of what a
// conjugate-gradient step does, so when ρ is small — diffusion over a time
// step much shorter than a cell's diffusion time — it reaches a tolerance
// for far less.
#pragma once

#include "sim/fluid/ConjugateGradient.h"
#include "sim/fluid/ParallelOps.h"
#include "sim/fluid/WavefrontSlices.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace eikon::sim {

// Solves A x = b from x = 0 until the largest residual met during a sweep is
// at most tolerance · max|b|, or maxIterations sweeps. A sweep meets the
// first colour's residuals before their update and the second colour's after
// the first colour's; the residual it leaves is 0 on the second colour and,
// on the first, Σ w · (the second colour's residual met) / diag, so where
// Σ_n w / diag_n <= 1 — the diffusion matrices it is used on — the x
// returned is at least as accurate as reported.
inline SolveStats redBlackGaussSeidel(const SevenPointOperator& a, const std::vector<double>& b,
                                      std::vector<double>& x, double tolerance, int maxIterations) {
    x.resize(b.size());
    const double bNorm = maxAbs(b);
    if (bNorm == 0.0) {
        std::fill(x.begin(), x.end(), 0.0);
        return {};
    }
    // x_c += r_c / diag_c on the cells of `colour` in slice k; returns max|r_c|.
    // The first sweep starts from x = 0: it clears the slice, and the first
    // colour, whose neighbours are all of the other colour, takes b / diag.
    auto relaxSlice = [&](int k, int colour, bool fromZero) {
        double largest = 0.0;
        const double bulkDiagonal = a.bulkDiagonal(), bulkInverse = a.bulkInverseDiagonal();
        for (int j = 0; j < a.size.y; ++j) {
            if (fromZero) {
                std::fill_n(x.begin() + static_cast<std::ptrdiff_t>(a.index(0, j, k)), a.size.x, 0.0);
                a.forRowCells(
                    j, k, (j + k + colour) & 1, 2,
                    [&](std::size_t c) {
                        x[c] = b[c] * a.inverseDiagonal(c);  // 0 off the unknowns
                        if (a.isUnknown(c)) largest = std::max(largest, std::abs(b[c]));
                    },
                    [&](std::size_t c) {
                        x[c] = b[c] * bulkInverse;
                        largest = std::max(largest, std::abs(b[c]));
                    });
                continue;
            }
            a.forRowCells(
                j, k, (j + k + colour) & 1, 2,
                [&](std::size_t c) {
                    if (!a.isUnknown(c)) return;  // x stays 0
                    const double residual = b[c] + a.neighbourSum(x, c) - a.diagonal(c) * x[c];
                    x[c] += residual * a.inverseDiagonal(c);
                    largest = std::max(largest, std::abs(residual));
                },
                [&](std::size_t c) {
                    const double residual = b[c] + a.bulkNeighbourSum(x, c) - bulkDiagonal * x[c];
                    x[c] += residual * bulkInverse;
                    largest = std::max(largest, std::abs(residual));
                });
        }
        return largest;
    };
    // Each sweep is one pass over memory, the second colour one slice behind
    // the first (WavefrontSlices.h).
    const auto larger = [](double u, double v) { return std::max(u, v); };
    SolveStats stats;
    while (stats.iterations < maxIterations) {
        const bool fromZero = stats.iterations == 0;
        const StageTotals residuals = runStagesAsWavefront(
            a.size.z, 2, a.passesInParallel(), 0.0,
            [&](int q, int k) { return relaxSlice(k, q, fromZero && q == 0); }, larger);
        ++stats.iterations;
        stats.relativeResidual = std::max(residuals[0], residuals[1]) / bNorm;
        if (stats.relativeResidual <= tolerance) break;
    }
    return stats;
}

}  // namespace eikon::sim
