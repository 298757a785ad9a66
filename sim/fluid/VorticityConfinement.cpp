#include "sim/fluid/VorticityConfinement.h"

#include "sim/fluid/CellForceOnFaces.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

namespace eikon::sim {

namespace {

using CellVectors = std::array<GridField, 3>;

// Calls f(i, j, k) for every cell, the z layers in parallel.
template <typename F>
void forEachCell(glm::ivec3 cells, F&& f) {
    tbb::parallel_for(0, cells.z, [&](int k) {
        for (int j = 0; j < cells.y; ++j)
            for (int i = 0; i < cells.x; ++i) f(i, j, k);
    });
}

// ∂φ/∂x_axis at cell c: central, one-sided at the box's edges, 0 on an axis one cell thick.
double derivative(const GridField& phi, glm::ivec3 c, int axis, double h) {
    glm::ivec3 low = c, high = c;
    low[axis] = std::max(c[axis] - 1, 0);
    high[axis] = std::min(c[axis] + 1, phi.size[axis] - 1);
    if (high[axis] == low[axis]) return 0.0;
    return (phi(high.x, high.y, high.z) - phi(low.x, low.y, low.z)) / ((high[axis] - low[axis]) * h);
}

}  // namespace

double confinementLength(const glm::dvec3& h) { return std::cbrt(h.x * h.y * h.z); }

void addVorticityConfinement(FluidState& state, const FluidDomain& domain, double epsilon, double dt) {
    if (epsilon == 0.0) return;
    MacGrid& flow = state.flow;
    const glm::ivec3 cells = domain.cells;
    const glm::dvec3 h = flow.h;
    // ū: each component the mean of its cell's two faces.
    CellVectors centred{flow.cellField(0.0), flow.cellField(0.0), flow.cellField(0.0)};
    forEachCell(cells, [&](int i, int j, int k) {
        for (int axis = 0; axis < 3; ++axis) {
            glm::ivec3 upper(i, j, k);
            upper[axis] += 1;
            centred[axis](i, j, k) = 0.5 * (flow.velocity[axis](i, j, k) + flow.velocity[axis](upper.x, upper.y, upper.z));
        }
    });
    // ω = ∇ × ū (eq. 9) and |ω|.
    CellVectors omega{flow.cellField(0.0), flow.cellField(0.0), flow.cellField(0.0)};
    GridField magnitude = flow.cellField(0.0);
    forEachCell(cells, [&](int i, int j, int k) {
        const glm::ivec3 c(i, j, k);
        auto d = [&](int component, int axis) { return derivative(centred[component], c, axis, h[axis]); };
        const glm::dvec3 w(d(2, 1) - d(1, 2), d(0, 2) - d(2, 0), d(1, 0) - d(0, 1));
        for (int a = 0; a < 3; ++a) omega[a](i, j, k) = w[a];
        magnitude(i, j, k) = glm::length(w);
    });
    // f = ε h (N × ω), N = ∇|ω| / |∇|ω|| (eqs. 10–11), zero in solid cells.
    const double scale = epsilon * confinementLength(h);
    CellVectors force{flow.cellField(0.0), flow.cellField(0.0), flow.cellField(0.0)};
    forEachCell(cells, [&](int i, int j, int k) {
        if (domain.isSolid(i, j, k)) return;
        const glm::ivec3 c(i, j, k);
        const glm::dvec3 eta(derivative(magnitude, c, 0, h.x), derivative(magnitude, c, 1, h.y),
                             derivative(magnitude, c, 2, h.z));
        const double length = glm::length(eta);
        if (length < kMinVorticityGradient) return;
        const glm::dvec3 w(omega[0](i, j, k), omega[1](i, j, k), omega[2](i, j, k));
        const glm::dvec3 f = scale * glm::cross(eta / length, w);
        for (int a = 0; a < 3; ++a) force[a](i, j, k) = f[a];
    });
    // Each free face: Δt times the mean of its two cells' force along its axis.
    for (int axis = 0; axis < 3; ++axis) {
        const GridField& f = force[axis];
        addCellForceOnFaces(flow.velocity[axis], domain, axis, dt,
                            [&](int i, int j, int k) { return f(i, j, k); });
    }
}

}  // namespace eikon::sim
