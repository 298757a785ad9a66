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

    // Displacement along the characteristic through g over time t (negative:
    // backward) by the midpoint rule, with the velocity at g given.
    glm::dvec3 displacement(const glm::dvec3& g, const glm::dvec3& velocityAtG, double t) const {
        return t * at(g + 0.5 * t * velocityAtG);
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

// Traces the characteristics through every cell centre both ways; the
// backward and forward steps start from the same velocity, sampled once.
// The velocity at the centre of a cell is the mean of its two faces per
// axis — what trilinear sampling gives there, without the gathers.
void traceCellCentres(const CellVelocity& flow, glm::ivec3 cells, double dt, AdvectionScratch& scratch) {
    const std::size_t count = static_cast<std::size_t>(cells.x) * cells.y * cells.z;
    scratch.cellBack.resize(count);
    scratch.cellAhead.resize(count);
    const std::array<GridField, 3>& u = scratch.tracing;
    tbb::parallel_for(0, cells.z, [&](int k) {
        std::size_t c = static_cast<std::size_t>(cells.x) * cells.y * k;
        for (int j = 0; j < cells.y; ++j) {
            const double* ux = &u[0].values[u[0].index(0, j, k)];
            const double* uyBelow = &u[1].values[u[1].index(0, j, k)];
            const double* uyAbove = &u[1].values[u[1].index(0, j + 1, k)];
            const double* uzBelow = &u[2].values[u[2].index(0, j, k)];
            const double* uzAbove = &u[2].values[u[2].index(0, j, k + 1)];
            for (int i = 0; i < cells.x; ++i, ++c) {
                const glm::dvec3 g = glm::dvec3(i, j, k) + 0.5;
                const glm::dvec3 velocity(0.5 * (ux[i] + ux[i + 1]), 0.5 * (uyBelow[i] + uyAbove[i]),
                                          0.5 * (uzBelow[i] + uzAbove[i]));
                scratch.cellBack[c] = glm::vec3(flow.displacement(g, velocity, -dt));
                scratch.cellAhead[c] = glm::vec3(flow.displacement(g, velocity, dt));
            }
        }
    });
}

// Where the characteristics through the samples of one lattice end, in that
// lattice's coordinates. Cell centres read their traced displacements. A face
// between two cells takes the mean of theirs: the displacement is a smooth
// field, so its linear interpolation is second order in h like the midpoint
// rule itself, and the three face lattices need no tracing of their own. A
// face on the edge of the grid has one neighbour and traces for itself.
class LatticeEnds {
public:
    // axis: the face lattice normal to it, or −1 for cell centres.
    LatticeEnds(const CellVelocity& flow, const AdvectionScratch& scratch, glm::ivec3 cells, int axis,
                glm::dvec3 offset, double dt)
        : flow_(flow), scratch_(scratch), cells_(cells), axis_(axis), offset_(offset), dt_(dt) {}

    // The backward (or forward) ends of row (j, k) of the lattice, rowLength samples.
    void backRow(int j, int k, int rowLength, glm::dvec3* ends) const {
        row(scratch_.cellBack, j, k, rowLength, -dt_, ends);
    }
    void aheadRow(int j, int k, int rowLength, glm::dvec3* ends) const {
        row(scratch_.cellAhead, j, k, rowLength, dt_, ends);
    }

private:
    const glm::vec3* cellRow(const std::vector<glm::vec3>& displacements, int j, int k) const {
        return displacements.data() + static_cast<std::size_t>(cells_.x) * (j + static_cast<std::size_t>(cells_.y) * k);
    }

    glm::dvec3 traced(int i, int j, int k, double t) const {
        const glm::dvec3 start = glm::dvec3(i, j, k) + offset_;
        return glm::dvec3(i, j, k) + flow_.displacement(start, flow_.at(start), t);
    }

    void row(const std::vector<glm::vec3>& displacements, int j, int k, int rowLength, double t,
             glm::dvec3* ends) const {
        if (axis_ < 0) {
            const glm::vec3* here = cellRow(displacements, j, k);
            for (int i = 0; i < rowLength; ++i) ends[i] = glm::dvec3(i, j, k) + glm::dvec3(here[i]);
            return;
        }
        if (axis_ == 0) {  // x faces: the cells on either side lie in the same row
            const glm::vec3* here = cellRow(displacements, j, k);
            ends[0] = traced(0, j, k, t);
            for (int i = 1; i + 1 < rowLength; ++i)
                ends[i] = glm::dvec3(i, j, k) + 0.5 * (glm::dvec3(here[i - 1]) + glm::dvec3(here[i]));
            ends[rowLength - 1] = traced(rowLength - 1, j, k, t);
            return;
        }
        const int along = axis_ == 1 ? j : k;  // y or z faces: the cells lie in the rows below and above
        if (along == 0 || along == cells_[axis_]) {
            for (int i = 0; i < rowLength; ++i) ends[i] = traced(i, j, k, t);
            return;
        }
        const glm::vec3* above = cellRow(displacements, j, k);
        const glm::vec3* below = axis_ == 1 ? cellRow(displacements, j - 1, k) : cellRow(displacements, j, k - 1);
        for (int i = 0; i < rowLength; ++i)
            ends[i] = glm::dvec3(i, j, k) + 0.5 * (glm::dvec3(below[i]) + glm::dvec3(above[i]));
    }

    const CellVelocity& flow_;
    const AdvectionScratch& scratch_;
    glm::ivec3 cells_;
    int axis_;
    glm::dvec3 offset_;
    double dt_;
};

// Grows (never shrinks) the per-field buffers to `fieldCount` fields of `layout`'s size.
void reserveGroup(AdvectionScratch::Group& group, const GridField& layout, std::size_t fieldCount) {
    if (group.forward.size() < fieldCount) {
        group.forward.resize(fieldCount);
        group.low.resize(fieldCount);
        group.high.resize(fieldCount);
    }
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
void advectGroup(const LatticeEnds& ends, const std::vector<const GridField*>& sources,
                 const std::vector<GridField*>& targets, AdvectionScratch::Group& group) {
    const GridField& layout = *sources.front();
    const glm::ivec3 n = layout.size;
    const std::size_t fieldCount = sources.size();
    reserveGroup(group, layout, fieldCount);
    std::vector<GridField>& forward = group.forward;  // φ̂ⁿ⁺¹ = A(φⁿ), the semi-Lagrangian result
    tbb::parallel_for(0, n.z, [&](int k) {
        std::vector<glm::dvec3> row(static_cast<std::size_t>(n.x));
        for (int j = 0; j < n.y; ++j) {
            ends.backRow(j, k, n.x, row.data());
            for (int i = 0; i < n.x; ++i) {
                const glm::dvec3& back = row[static_cast<std::size_t>(i)];
                const std::size_t s = layout.index(i, j, k);
                for (std::size_t f = 0; f < fieldCount; ++f) {
                    const StencilSample sample = sampleWithBounds(*sources[f], back);
                    forward[f].values[s] = sample.value;
                    group.low[f][s] = sample.min;
                    group.high[f][s] = sample.max;
                }
            }
        }
    });
    tbb::parallel_for(0, n.z, [&](int k) {
        std::vector<glm::dvec3> row(static_cast<std::size_t>(n.x));
        for (int j = 0; j < n.y; ++j) {
            ends.aheadRow(j, k, n.x, row.data());
            for (int i = 0; i < n.x; ++i) {
                const glm::dvec3& ahead = row[static_cast<std::size_t>(i)];
                const std::size_t s = layout.index(i, j, k);
                for (std::size_t f = 0; f < fieldCount; ++f) {
                    const double roundTrip = sampleTrilinear(forward[f], ahead);  // φ̂ⁿ = Aᴿ(φ̂ⁿ⁺¹)
                    const double corrected = forward[f].values[s] + 0.5 * (sources[f]->values[s] - roundTrip);
                    targets[f]->values[s] = std::clamp(corrected, group.low[f][s], group.high[f][s]);
                }
            }
        }
    });
}

// The scalars and, with `velocity`, the face velocities (its own start
// values) through flow's velocity. A uniform field is its own MacCormack step
// (every blend of equal values is that value, and the correction vanishes),
// so it is left as it is.
void advectFields(const MacGrid& flow, const std::vector<GridField*>& scalars, MacGrid* velocity, double dt,
                  AdvectionScratch& scratch) {
    std::vector<GridField*> varying;
    for (GridField* field : scalars)
        if (!isUniform(field->values)) varying.push_back(field);
    bool velocityVaries[3] = {false, false, false};
    for (int axis = 0; velocity && axis < 3; ++axis) velocityVaries[axis] = !isUniform(velocity->velocity[axis].values);
    if (varying.empty() && !velocityVaries[0] && !velocityVaries[1] && !velocityVaries[2]) return;

    toCellsPerSecond(flow, scratch.tracing);
    const CellVelocity cellVelocity(scratch.tracing);
    const glm::ivec3 cells = flow.grid.resolution;
    traceCellCentres(cellVelocity, cells, dt, scratch);
    if (!varying.empty()) {
        const std::vector<const GridField*> sources(varying.begin(), varying.end());
        advectGroup(LatticeEnds(cellVelocity, scratch, cells, -1, glm::dvec3(0.5), dt), sources, varying,
                    scratch.scalars);
    }
    for (int axis = 0; axis < 3; ++axis) {
        if (!velocityVaries[axis]) continue;
        GridField& u = velocity->velocity[axis];
        scratch.start[axis] = u;  // reuses the buffer of the last call
        advectGroup(LatticeEnds(cellVelocity, scratch, cells, axis, u.offset, dt), {&scratch.start[axis]}, {&u},
                    scratch.velocity[axis]);
    }
}

}  // namespace

void advect(MacGrid& mac, const std::vector<GridField*>& scalars, double dt, AdvectionScratch& scratch) {
    advectFields(mac, scalars, &mac, dt, scratch);
}

void advectScalars(const MacGrid& flow, const std::vector<GridField*>& scalars, double dt) {
    AdvectionScratch scratch;
    advectFields(flow, scalars, nullptr, dt, scratch);
}

void advectVelocity(MacGrid& mac, double dt) {
    AdvectionScratch scratch;
    advectFields(mac, {}, &mac, dt, scratch);
}

}  // namespace eikon::sim
