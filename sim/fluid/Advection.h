// Advection by the MacCormack scheme of Selle, Fedkiw, Kim, Liu and Rossignac
// 2008, "An unconditionally stable MacCormack method", Eqs. 3–5: a
// semi-Lagrangian step back along the flow (Stam 1999, "Stable Fluids", §2.2),
// a step forward from its result to estimate the error, and half that error
// added back. The result is clamped to the smallest and largest of the eight
// values the backward step blended (their §3.1 limiter), so no new extrema
// appear and the scheme stays unconditionally stable. Characteristics are
// traced with the midpoint rule through the velocity of the start of the step.
#pragma once

#include "sim/fluid/MacGrid.h"

#include <array>
#include <vector>

namespace eikon::sim {

// Buffers of the MacCormack steps kept between calls, so that advection
// allocates nothing once they have their size. One call at a time.
struct AdvectionScratch {
    // Per lattice advected together: where each sample's forward
    // characteristic ends (lattice coordinates), and φ̂ⁿ⁺¹ = A(φⁿ) and the
    // limiter bounds per field.
    struct Group {
        std::vector<glm::dvec3> ahead;
        std::vector<GridField> forward;
        std::vector<std::vector<double>> low, high;
    };
    Group scalars;
    std::array<Group, 3> velocity;
    std::array<GridField, 3> start;    // the face velocities at the start of the step
    std::array<GridField, 3> tracing;  // the flow in cells per second, for tracing characteristics
};

// Advects cell-centred scalars through flow.velocity over dt, in place.
void advectScalars(const MacGrid& flow, const std::vector<GridField*>& scalars, double dt, AdvectionScratch& scratch);

// Advects each velocity component of mac through mac's own velocity at the
// start of the step (u·∇u), in place.
void advectVelocity(MacGrid& mac, double dt, AdvectionScratch& scratch);

// The same with buffers of their own, for one-off calls.
void advectScalars(const MacGrid& flow, const std::vector<GridField*>& scalars, double dt);
void advectVelocity(MacGrid& mac, double dt);

}  // namespace eikon::sim
