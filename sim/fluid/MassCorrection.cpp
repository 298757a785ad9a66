#include "sim/fluid/MassCorrection.h"

#include "sim/fluid/ParallelOps.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace eikon::sim {

void restoreTotal(GridField& field, double target, double low, double high) {
    if (!(high > low)) return;
    std::vector<double> weight(field.count());
    using Range = tbb::blocked_range<std::size_t>;
    tbb::parallel_for(Range(0, field.count(), 4096), [&](const Range& r) {
        for (std::size_t i = r.begin(); i < r.end(); ++i) {
            const double v = std::clamp(field.values[i], low, high);
            weight[i] = (v - low) * (high - v) / (high - low);
        }
    });
    const double total = sum(weight);
    if (total <= 0.0) return;
    // Each cell moves by scale·w_c, and w_c <= the room to either bound, so |scale| <= 1 keeps the range.
    const double scale = std::clamp((target - sum(field.values)) / total, -1.0, 1.0);
    axpy(scale, weight, field.values);
}

}  // namespace eikon::sim
