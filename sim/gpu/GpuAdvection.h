// MacCormack advection ([Selle08] eqs. 3–5) on the GPU, the discretisation of
// sim/fluid/Advection.h to float rounding: characteristics traced once per
// cell centre by the midpoint rule ([Stam99] §2.2) through the velocity at the
// start of the step, in cell coordinates; face lattices take the mean of their
// two cells' displacements and faces on the walls trace for themselves; a
// semi-Lagrangian step back, a step forward from its result, half the round
// trip's error added back, clamped to the eight values the backward step
// blended (the limiter of [Selle08] §3.1). Passes: shaders/sim/advection_*.
//
// Unlike the CPU, uniform fields are advected too: a uniform field is its own
// MacCormack step exactly (every blend of equal values is that value and the
// correction vanishes), so the result is the same, without a readback to ask.
#pragma once

#include "gl/GlObjects.h"
#include "sim/gpu/GpuField.h"

#include <glm/vec3.hpp>

#include <array>
#include <vector>

namespace eikon::sim::gpu {

class GpuAdvection {
public:
    // cells: the grid's cells per axis; h: the cell edge per axis, m.
    GpuAdvection(glm::ivec3 cells, glm::dvec3 h);

    // As sim::advect(mac, scalars, dt, scratch): advects the cell-centred
    // scalars and each velocity component (its own start values) through the
    // velocity at the start of the step, in place.
    void advect(std::array<GpuField, 3>& velocity, const std::vector<GpuField*>& scalars, double dt);

private:
    // Displacements of every cell centre and wall face over −Δt and +Δt.
    void trace(const std::array<GpuField, 3>& velocity, double dt);
    // The MacCormack step of one field on lattice `axis` (−1: cell centres).
    void advectField(GpuField& field, int axis);

    glm::ivec3 cells_;
    glm::dvec3 h_;
    gl::Buffer backward_, forward_;       // displacement records, vec4 (shaders/sim/advection_lattice.glsl)
    gl::Buffer predicted_, low_, high_;   // φ̂ⁿ⁺¹ and the limiter's bounds, per sample of the largest lattice
    gl::Program trace_, predict_, correct_;
};

}  // namespace eikon::sim::gpu
