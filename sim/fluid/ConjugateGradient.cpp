#include "sim/fluid/ConjugateGradient.h"

#include "sim/fluid/ParallelOps.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace eikon::sim {

namespace {

// x += α p and r −= α q in one pass; returns max|r|.
double stepSolution(double alpha, const std::vector<double>& p, const std::vector<double>& q, std::vector<double>& x,
                    std::vector<double>& r) {
    using Range = tbb::blocked_range<std::size_t>;
    return tbb::parallel_reduce(
        Range(0, x.size(), 4096), 0.0,
        [&](const Range& range, double largest) {
            for (std::size_t i = range.begin(); i < range.end(); ++i) {
                x[i] += alpha * p[i];
                r[i] -= alpha * q[i];
                largest = std::max(largest, std::abs(r[i]));
            }
            return largest;
        },
        [](double u, double v) { return std::max(u, v); });
}

// z = M⁻¹ r, kept in the complement of the null space when A is singular; returns r · z.
double precondition(const Preconditioner& preconditioner, const SevenPointOperator& a, bool singular,
                    const std::vector<double>& r, std::vector<double>& z) {
    const double rz = preconditioner(r, z);
    if (!singular) return rz;
    a.removeMeanOverUnknowns(z);
    return dot(r, z);
}

}  // namespace

SolveStats conjugateGradient(const SevenPointOperator& a, const std::vector<double>& b, std::vector<double>& x,
                             const Preconditioner& preconditioner, double tolerance, int maxIterations,
                             bool singular, CgWorkspace& work) {
    const std::size_t n = b.size();
    const double bNorm = maxAbs(b);
    if (bNorm == 0.0) {
        x.assign(n, 0.0);
        return {};
    }
    std::vector<double>& r = work.r;
    std::vector<double>& z = work.z;
    std::vector<double>& q = work.q;
    std::vector<double>& p = work.p;
    r.resize(n);
    z.resize(n);
    q.resize(n);
    a.residual(b, x, r);
    if (singular) a.removeMeanOverUnknowns(r);
    SolveStats stats{0, maxAbs(r) / bNorm};
    if (stats.relativeResidual <= tolerance) return stats;

    double rho = precondition(preconditioner, a, singular, r, z);
    p = z;
    while (stats.iterations < maxIterations) {
        const double alpha = rho / a.applyAndDot(p, q);
        ++stats.iterations;
        stats.relativeResidual = stepSolution(alpha, p, q, x, r) / bNorm;
        if (stats.relativeResidual <= tolerance) break;
        const double rhoNext = precondition(preconditioner, a, singular, r, z);
        const double beta = rhoNext / rho;
        rho = rhoNext;
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096), [&](const tbb::blocked_range<std::size_t>& range) {
            for (std::size_t i = range.begin(); i < range.end(); ++i) p[i] = z[i] + beta * p[i];
        });
    }
    return stats;
}

Preconditioner jacobiPreconditioner(const SevenPointOperator& a) {
    return [&a](const std::vector<double>& r, std::vector<double>& z) {
        z.resize(r.size());
        using Range = tbb::blocked_range<std::size_t>;
        return tbb::parallel_deterministic_reduce(  // the same bits run after run
            Range(0, r.size(), 4096), 0.0,
            [&](const Range& range, double partial) {
                for (std::size_t i = range.begin(); i < range.end(); ++i) {
                    z[i] = r[i] * a.inverseDiagonal(i);
                    partial += r[i] * z[i];
                }
                return partial;
            },
            std::plus<>());
    };
}

}  // namespace eikon::sim
