// Advection by the MacCormack scheme ([Selle08] eqs. 3–5): a semi-Lagrangian
// step back along the flow ([Stam99] §2.2), a step forward from its result to
// estimate the error, and half that error added back. The result is clamped
// to the smallest and largest of the eight values the backward step blended
// (the limiter of [Selle08] §3.1), so no new extrema appear and the scheme
// stays unconditionally stable. Characteristics are traced with the midpoint
// rule through the velocity of the start of the step, once per cell centre;
// the face velocities reuse them (Advection.cpp).
#pragma once

#include "sim/fluid/MacGrid.h"

#include <glm/vec3.hpp>

#include <array>
#include <vector>

namespace eikon::sim {

// Buffers of the MacCormack steps kept between calls, so that advection
// allocates nothing once they have their size. One call at a time.
struct AdvectionScratch {
    // Per lattice advected together: φ̂ⁿ⁺¹ = A(φⁿ) and the limiter bounds, per field.
    struct Group {
        std::vector<GridField> forward;
        std::vector<std::vector<double>> low, high;
    };
    Group scalars;
    std::array<Group, 3> velocity;
    std::array<GridField, 3> start;    // the face velocities at the start of the step
    std::array<GridField, 3> tracing;  // the flow in cells per second, for tracing characteristics
    // Per cell centre, the displacement in cells along its characteristic
    // over −Δt and +Δt (float: 1e-7 of a displacement is far below a cell).
    std::vector<glm::vec3> cellBack, cellAhead;
};

// Advects the cell-centred scalars and each velocity component of mac
// (u·∇u) through mac's velocity at the start of the step, in place.
void advect(MacGrid& mac, const std::vector<GridField*>& scalars, double dt, AdvectionScratch& scratch);

// Only the scalars through flow, or only the velocity, with buffers of their
// own, for one-off calls.
void advectScalars(const MacGrid& flow, const std::vector<GridField*>& scalars, double dt);
void advectVelocity(MacGrid& mac, double dt);

}  // namespace eikon::sim
