#include "sim/fluid/FiniteCheck.h"

#include "bridge/core/Error.h"
#include "bridge/core/NumberFormat.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>

namespace eikon::sim {

void requireFinite(const GridField& field, const std::string& name, const std::string& sample,
                   const SolverPhase& phase) {
    using Range = tbb::blocked_range<std::size_t>;
    const std::size_t none = field.count();
    const std::size_t first = tbb::parallel_reduce(
        Range(0, field.count(), 4096), none,
        [&](const Range& r, std::size_t found) {
            for (std::size_t i = r.begin(); i < r.end() && i < found; ++i)
                if (!std::isfinite(field.values[i])) return i;
            return found;
        },
        [](std::size_t a, std::size_t b) { return std::min(a, b); });
    if (first == none) return;
    throwNotFinite(name, sample, field.size, first, field.values[first], phase);
}

void throwNotFinite(const std::string& name, const std::string& sample, glm::ivec3 size, std::size_t index,
                    double value, const SolverPhase& phase) {
    const auto nx = static_cast<std::size_t>(size.x);
    const auto ny = static_cast<std::size_t>(size.y);
    const std::string where = std::string(phase.keys) + " (the solver's " + name + " at " + sample + " (" +
                              std::to_string(index % nx) + ", " + std::to_string((index / nx) % ny) + ", " +
                              std::to_string(index / (nx * ny)) + ") of sim.resolution, " + phase.when + ")";
    throw NumericalBreakdown(where, "a finite value", formatNumber(value));
}

}  // namespace eikon::sim
