// Pressure projection ([Bridson15] ch. 5; Chorin's projection as in
// [Stam99] §2): find p with L p = −∇·u* on the fluid cells
// (L the positive Laplacian of poissonOperator) and set u = u* − ∇p, so that
// the discrete divergence of u vanishes up to the solver tolerance. p absorbs
// Δt/ρ (units m²/s). Solved by conjugate gradients preconditioned with a
// multigrid V-cycle ([McAdams10]).
#pragma once

#include "sim/fluid/Boundaries.h"
#include "sim/fluid/ConjugateGradient.h"
#include "sim/fluid/Multigrid.h"

namespace eikon::sim {

class PressureSolver {
public:
    // Builds the multigrid hierarchy for this domain; rebuild when solids change.
    explicit PressureSolver(const FluidDomain& domain, glm::dvec3 h);

    // Projects mac.velocity; `pressure` (cell-centred) is the initial guess and
    // receives p. Stops at max|∇·u| <= tolerance · max|∇·u*| or maxIterations.
    SolveStats project(MacGrid& mac, GridField& pressure, double tolerance, int maxIterations) const;

private:
    FluidDomain domain_;
    MultigridPreconditioner multigrid_;
    bool singular_;  // no open face: p is determined up to a constant
    // Scratch of project(), kept so a projection allocates nothing: one call at a time.
    mutable std::vector<double> rhs_;
    mutable CgWorkspace work_;
};

}  // namespace eikon::sim
