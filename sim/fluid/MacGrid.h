// The staggered (marker-and-cell) velocity grid of [Harlow65], as in
// [Bridson15] §2.4: cell (i, j, k) holds scalars at its centre; velocity
// component a lives on the faces normal to axis a, so u has (nx + 1)·ny·nz
// samples. Divergence and pressure gradients then are exact central
// differences over one cell.
#pragma once

#include "bridge/grid/GridSpec.h"
#include "sim/field/GridField.h"

#include <array>

namespace eikon::sim {

struct MacGrid {
    GridSpec grid;                     // cells and their world box
    glm::dvec3 h{1.0};                 // cell edge per axis, m
    std::array<GridField, 3> velocity; // face-normal components u, v, w in m/s

    explicit MacGrid(const GridSpec& cells);

    // A cell-centred field filled with `value`.
    GridField cellField(double value) const;

    // World position of a field's sample, and a world point in its lattice coordinates.
    glm::dvec3 position(const GridField& field, int i, int j, int k) const {
        return grid.boundsMin + (glm::dvec3(i, j, k) + field.offset) * h;
    }
    glm::dvec3 lattice(const GridField& field, const glm::dvec3& x) const {
        return (x - grid.boundsMin) / h - field.offset;
    }

    // Velocity at a world point: each component interpolated on its own faces.
    glm::dvec3 velocityAt(const glm::dvec3& x) const {
        return {sampleTrilinear(velocity[0], lattice(velocity[0], x)),
                sampleTrilinear(velocity[1], lattice(velocity[1], x)),
                sampleTrilinear(velocity[2], lattice(velocity[2], x))};
    }

    // (∇·u) of cell (i, j, k): Σ_a (u_a(upper face) − u_a(lower face)) / h_a.
    double divergence(int i, int j, int k) const;

    // max over faces and axes of |u_a| / h_a: a substep Δt has CFL number Δt times this.
    double maxCellCrossingRate() const;
};

}  // namespace eikon::sim
