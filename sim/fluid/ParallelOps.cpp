#include "sim/fluid/ParallelOps.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace eikon::sim {

namespace {

using Range = tbb::blocked_range<std::size_t>;
constexpr std::size_t kGrain = 4096;

// Deterministic: the range splits the same way whatever the threads do, so a
// sum (and the solver built on it) gives the same bits run after run.
template <class Body>
double reduceSum(std::size_t n, Body body) {
    return tbb::parallel_deterministic_reduce(
        Range(0, n, kGrain), 0.0,
        [&](const Range& r, double partial) {
            for (std::size_t i = r.begin(); i < r.end(); ++i) partial += body(i);
            return partial;
        },
        std::plus<>());
}

}  // namespace

double dot(const std::vector<double>& a, const std::vector<double>& b) {
    return reduceSum(a.size(), [&](std::size_t i) { return a[i] * b[i]; });
}

double sum(const std::vector<double>& a) {
    return reduceSum(a.size(), [&](std::size_t i) { return a[i]; });
}

double maxAbs(const std::vector<double>& a) {
    return tbb::parallel_reduce(
        Range(0, a.size(), kGrain), 0.0,
        [&](const Range& r, double partial) {
            for (std::size_t i = r.begin(); i < r.end(); ++i) partial = std::max(partial, std::abs(a[i]));
            return partial;
        },
        [](double x, double y) { return std::max(x, y); });
}

bool isUniform(const std::vector<double>& a) {
    if (a.empty()) return true;
    const double first = a.front();
    // A field that varies anywhere much usually varies at one of a few
    // hundred spread-out entries: look there before reading all of it.
    constexpr std::size_t kProbes = 509;
    for (std::size_t i = 0; i < a.size(); i += a.size() / kProbes + 1)
        if (a[i] != first) return false;
    return tbb::parallel_reduce(
        Range(0, a.size(), kGrain), true,
        [&](const Range& r, bool uniform) {
            for (std::size_t i = r.begin(); uniform && i < r.end(); ++i) uniform = a[i] == first;
            return uniform;
        },
        [](bool x, bool y) { return x && y; });
}

void axpy(double alpha, const std::vector<double>& x, std::vector<double>& y) {
    tbb::parallel_for(Range(0, x.size(), kGrain), [&](const Range& r) {
        for (std::size_t i = r.begin(); i < r.end(); ++i) y[i] += alpha * x[i];
    });
}

}  // namespace eikon::sim
