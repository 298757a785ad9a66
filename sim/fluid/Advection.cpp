#include "sim/fluid/Advection.h"

#include "sim/fluid/ParallelOps.h"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace eikon::sim {

namespace {

// Characteristics are traced in cell coordinates g = (x − boundsMin) / h, in
// which sample (i, j, k) of a lattice sits at (i, j, k) + offset and the
// velocity is in cells per second: no division per sample.
class CellVelocity {
public:
    explicit CellVelocity(const std::array<GridField, 3>& cellsPerSecond) : u_(cellsPerSecond) {}

    glm::dvec3 at(const glm::dvec3& g) const {
        return {sampleTrilinear(u_[0], g - u_[0].offset), sampleTrilinear(u_[1], g - u_[1].offset),
                sampleTrilinear(u_[2], g - u_[2].offset)};
    }

    // Ends of the characteristic through g after times −dt and +dt by the
    // midpoint rule; both start from the velocity at g, sampled once.
    void traceBothWays(const glm::dvec3& g, double dt, glm::dvec3& back, glm::dvec3& ahead) const {
        const glm::dvec3 halfStep = 0.5 * dt * at(g);
        back = g - dt * at(g - halfStep);
        ahead = g + dt * at(g + halfStep);
    }

private:
    const std::array<GridField, 3>& u_;
};

// The face velocities of `mac` divided by the cell edge along their axis.
void toCellsPerSecond(const MacGrid& mac, std::array<GridField, 3>& cellsPerSecond) {
    for (int axis = 0; axis < 3; ++axis) {
        const GridField& u = mac.velocity[axis];
        GridField& scaled = cellsPerSecond[axis];
        scaled.size = u.size;
        scaled.offset = u.offset;
        scaled.values.resize(u.count());
        const double invH = 1.0 / mac.h[axis];
        tbb::parallel_for(0, u.size.z, [&](int k) {
            for (std::size_t s = u.index(0, 0, k), end = s + static_cast<std::size_t>(u.size.x) * u.size.y; s < end; ++s)
                scaled.values[s] = u.values[s] * invH;
        });
    }
}

// Grows (never shrinks) the per-field buffers to `fieldCount` fields of `layout`'s size.
void reserveGroup(AdvectionScratch::Group& group, const GridField& layout, std::size_t fieldCount) {
    if (group.forward.size() < fieldCount) {
        group.forward.resize(fieldCount);
        group.low.resize(fieldCount);
        group.high.resize(fieldCount);
    }
    group.ahead.resize(layout.count());
    for (std::size_t f = 0; f < fieldCount; ++f) {
        group.forward[f].size = layout.size;
        group.forward[f].offset = layout.offset;
        group.forward[f].values.resize(layout.count());  // every sample is written below
        group.low[f].resize(layout.count());
        group.high[f].resize(layout.count());
    }
}

// MacCormack step for fields that share one lattice (size and offset):
// sources hold φⁿ, targets receive φⁿ⁺¹ (they may alias the sources).
void advectGroup(const CellVelocity& flow, const std::vector<const GridField*>& sources,
                 const std::vector<GridField*>& targets, double dt, AdvectionScratch::Group& group) {
    const GridField& layout = *sources.front();
    const glm::ivec3 n = layout.size;
    const glm::dvec3 offset = layout.offset;
    const std::size_t fieldCount = sources.size();
    reserveGroup(group, layout, fieldCount);
    std::vector<GridField>& forward = group.forward;  // φ̂ⁿ⁺¹ = A(φⁿ), the semi-Lagrangian result
    tbb::parallel_for(0, n.z, [&](int k) {
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                const std::size_t s = layout.index(i, j, k);
                glm::dvec3 back;
                flow.traceBothWays(glm::dvec3(i, j, k) + offset, dt, back, group.ahead[s]);
                back -= offset;
                group.ahead[s] -= offset;
                for (std::size_t f = 0; f < fieldCount; ++f) {
                    const StencilSample sample = sampleWithBounds(*sources[f], back);
                    forward[f].values[s] = sample.value;
                    group.low[f][s] = sample.min;
                    group.high[f][s] = sample.max;
                }
            }
    });
    tbb::parallel_for(0, n.z, [&](int k) {
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                const std::size_t s = layout.index(i, j, k);
                for (std::size_t f = 0; f < fieldCount; ++f) {
                    const double roundTrip = sampleTrilinear(forward[f], group.ahead[s]);  // φ̂ⁿ = Aᴿ(φ̂ⁿ⁺¹)
                    const double corrected = forward[f].values[s] + 0.5 * (sources[f]->values[s] - roundTrip);
                    targets[f]->values[s] = std::clamp(corrected, group.low[f][s], group.high[f][s]);
                }
            }
    });
}

}  // namespace

// A uniform field is its own MacCormack step (every blend of equal values is
// that value, and the correction vanishes), so it is left as it is.
void advectScalars(const MacGrid& flow, const std::vector<GridField*>& scalars, double dt,
                   AdvectionScratch& scratch) {
    std::vector<GridField*> varying;
    for (GridField* field : scalars)
        if (!isUniform(field->values)) varying.push_back(field);
    if (varying.empty()) return;
    toCellsPerSecond(flow, scratch.tracing);
    const std::vector<const GridField*> sources(varying.begin(), varying.end());
    advectGroup(CellVelocity(scratch.tracing), sources, varying, dt, scratch.scalars);
}

void advectVelocity(MacGrid& mac, double dt, AdvectionScratch& scratch) {
    toCellsPerSecond(mac, scratch.tracing);
    const CellVelocity flow(scratch.tracing);
    for (int axis = 0; axis < 3; ++axis) {
        if (isUniform(mac.velocity[axis].values)) continue;
        scratch.start[axis] = mac.velocity[axis];  // reuses the buffer of the last call
        advectGroup(flow, {&scratch.start[axis]}, {&mac.velocity[axis]}, dt, scratch.velocity[axis]);
    }
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
