// Jacobi iteration (Saad, "Iterative Methods for Sparse Linear Systems",
// §4.1): x ← x + D⁻¹ (b − A x), with D the diagonal of a seven-point
// operator. For a strictly diagonally dominant A, such as the backward-Euler
// diffusion matrix I + Δt·D·L, the error contracts by at least
// ρ = max_c Σ_n w / diag_c per sweep. A sweep reads and writes a quarter of
// what a conjugate-gradient step does (no dot products, no search
// direction), so when ρ is small — diffusion over a time step much shorter
// than a cell's diffusion time — it reaches a tolerance for less than CG.
#pragma once

#include "sim/fluid/ConjugateGradient.h"
#include "sim/fluid/ParallelOps.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace eikon::sim {

// A diagonal entry and its reciprocal; {0, 0} for a cell that is not an unknown.
struct DiagonalEntry {
    double value;
    double inverse;
};

// Solves A x = b from the x given, until max|b − A x| <= tolerance · max|b|
// or maxIterations sweeps, with A's diagonal from diagonalOf(c) (the
// operator's own diag is not read, so a caller may tabulate it); `next` is
// scratch. The residual is that of the iterate before the last sweep, so
// the x returned is at least that accurate.
template <class DiagonalOf>
SolveStats jacobiIteration(const SevenPointOperator& a, const DiagonalOf& diagonalOf, const std::vector<double>& b,
                           std::vector<double>& x, std::vector<double>& next, double tolerance, int maxIterations) {
    const double bNorm = maxAbs(b);
    if (bNorm == 0.0) {
        x.assign(b.size(), 0.0);
        return {};
    }
    next.resize(x.size());
    using Slices = tbb::blocked_range<int>;
    auto sweep = [&] {  // next = x + D⁻¹ (b − A x); returns max|b − A x|
        return tbb::parallel_reduce(
            Slices(0, a.size.z), 0.0,
            [&](const Slices& slices, double largest) {
                for (std::size_t c = a.index(0, 0, slices.begin()), end = a.index(0, 0, slices.end()); c < end; ++c) {
                    const DiagonalEntry diagonal = diagonalOf(c);
                    if (diagonal.value == 0.0) {
                        next[c] = 0.0;
                        continue;
                    }
                    const double residual = b[c] + a.neighbourSum(x, c) - diagonal.value * x[c];
                    next[c] = x[c] + residual * diagonal.inverse;
                    largest = std::max(largest, std::abs(residual));
                }
                return largest;
            },
            [](double u, double v) { return std::max(u, v); });
    };
    SolveStats stats;
    while (stats.iterations < maxIterations) {
        const double residual = sweep();
        std::swap(x, next);
        ++stats.iterations;
        stats.relativeResidual = residual / bNorm;
        if (stats.relativeResidual <= tolerance) break;
    }
    return stats;
}

}  // namespace eikon::sim
