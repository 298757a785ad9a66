#include "sim/fluid/Advection.h"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace eikon::sim {

namespace {

// End of the characteristic through x after time t (negative: backward), midpoint rule.
glm::dvec3 trace(const MacGrid& flow, const glm::dvec3& x, double t) {
    const glm::dvec3 mid = x + 0.5 * t * flow.velocityAt(x);
    return x + t * flow.velocityAt(mid);
}

// MacCormack step for fields that share one lattice (size and offset):
// sources hold φⁿ, targets receive φⁿ⁺¹ (they may alias the sources).
void advectGroup(const MacGrid& flow, const std::vector<const GridField*>& sources,
                 const std::vector<GridField*>& targets, double dt, AdvectionScratch& scratch) {
    const GridField& layout = *sources.front();
    const glm::ivec3 n = layout.size;
    const std::size_t fieldCount = sources.size();
    std::vector<GridField>& forward = scratch.forward;  // φ̂ⁿ⁺¹ = A(φⁿ), the semi-Lagrangian result
    std::vector<std::vector<double>>& low = scratch.low;
    std::vector<std::vector<double>>& high = scratch.high;
    forward.resize(fieldCount);
    low.resize(fieldCount);
    high.resize(fieldCount);
    for (std::size_t f = 0; f < fieldCount; ++f) {
        forward[f].size = layout.size;
        forward[f].offset = layout.offset;
        forward[f].values.resize(layout.count());  // every sample is written below
        low[f].resize(layout.count());
        high[f].resize(layout.count());
    }
    tbb::parallel_for(0, n.z, [&](int k) {
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                const glm::dvec3 back = flow.lattice(layout, trace(flow, flow.position(layout, i, j, k), -dt));
                const std::size_t s = layout.index(i, j, k);
                for (std::size_t f = 0; f < fieldCount; ++f) {
                    const StencilSample sample = sampleWithBounds(*sources[f], back);
                    forward[f].values[s] = sample.value;
                    low[f][s] = sample.min;
                    high[f][s] = sample.max;
                }
            }
    });
    tbb::parallel_for(0, n.z, [&](int k) {
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                const glm::dvec3 ahead = flow.lattice(layout, trace(flow, flow.position(layout, i, j, k), dt));
                const std::size_t s = layout.index(i, j, k);
                for (std::size_t f = 0; f < fieldCount; ++f) {
                    const double roundTrip = sampleTrilinear(forward[f], ahead);  // φ̂ⁿ = Aᴿ(φ̂ⁿ⁺¹)
                    const double corrected = forward[f].values[s] + 0.5 * (sources[f]->values[s] - roundTrip);
                    targets[f]->values[s] = std::clamp(corrected, low[f][s], high[f][s]);
                }
            }
    });
}

}  // namespace

void advectScalars(const MacGrid& flow, const std::vector<GridField*>& scalars, double dt,
                   AdvectionScratch& scratch) {
    if (scalars.empty()) return;
    const std::vector<const GridField*> sources(scalars.begin(), scalars.end());
    advectGroup(flow, sources, scalars, dt, scratch);
}

void advectVelocity(MacGrid& mac, double dt, AdvectionScratch& scratch) {
    if (scratch.start) {
        *scratch.start = mac;  // reuses the buffers of the last call
    } else {
        scratch.start.emplace(mac);
    }
    const MacGrid& start = *scratch.start;
    for (int axis = 0; axis < 3; ++axis)
        advectGroup(start, {&start.velocity[axis]}, {&mac.velocity[axis]}, dt, scratch);
}

void advectScalars(const MacGrid& flow, const std::vector<GridField*>& scalars, double dt) {
    AdvectionScratch scratch;
    advectScalars(flow, scalars, dt, scratch);
}

void advectVelocity(MacGrid& mac, double dt) {
    AdvectionScratch scratch;
    advectVelocity(mac, dt, scratch);
}

}  // namespace eikon::sim
