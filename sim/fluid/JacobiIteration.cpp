#include "sim/fluid/JacobiIteration.h"

#include "sim/fluid/ParallelOps.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace eikon::sim {

namespace {

// next = D⁻¹ (b + N x); returns max|D (next − x)| = max|b − A x|.
double sweep(const SevenPointOperator& a, const std::vector<double>& b, const std::vector<double>& x,
             std::vector<double>& next) {
    using Slices = tbb::blocked_range<int>;
    return tbb::parallel_reduce(
        Slices(0, a.size.z), 0.0,
        [&](const Slices& slices, double largest) {
            for (std::size_t c = a.index(0, 0, slices.begin()), end = a.index(0, 0, slices.end()); c < end; ++c) {
                if (a.diag[c] == 0.0) {
                    next[c] = 0.0;
                    continue;
                }
                next[c] = (b[c] + a.neighbourSum(x, c)) / a.diag[c];
                largest = std::max(largest, std::abs(a.diag[c] * (next[c] - x[c])));
            }
            return largest;
        },
        [](double u, double v) { return std::max(u, v); });
}

}  // namespace

SolveStats jacobiIteration(const SevenPointOperator& a, const std::vector<double>& b, std::vector<double>& x,
                           std::vector<double>& next, double tolerance, int maxIterations) {
    const double bNorm = maxAbs(b);
    if (bNorm == 0.0) {
        x.assign(b.size(), 0.0);
        return {};
    }
    next.resize(x.size());
    SolveStats stats;
    while (stats.iterations < maxIterations) {
        const double residual = sweep(a, b, x, next);
        std::swap(x, next);
        ++stats.iterations;
        stats.relativeResidual = residual / bNorm;
        if (stats.relativeResidual <= tolerance) break;
    }
    return stats;
}

}  // namespace eikon::sim
