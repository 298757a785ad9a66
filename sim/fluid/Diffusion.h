// Implicit diffusion, ∂φ/∂t = D ∇²φ by backward Euler (Stam 1999, "Stable
// Fluids", §2.3): (I + Δt·D·L) φⁿ⁺¹ = φⁿ with L the positive seven-point
// Laplacian, unconditionally stable for any Δt·D/h². Solved for the
// increment δ = φⁿ⁺¹ − φⁿ by Jacobi-preconditioned conjugate gradients, so the
// tolerance is relative to the change, not to the (possibly large) values.
#pragma once

#include "sim/fluid/ConjugateGradient.h"
#include "sim/fluid/GridField.h"

#include <cstdint>
#include <vector>

namespace eikon::sim {

// How a sample takes part: Free samples diffuse; Fixed ones keep their value
// and act as Dirichlet neighbours (a held temperature, a wall velocity);
// Excluded ones (inside solids) neither change nor exchange anything.
// Edges of the lattice are Neumann: no flux leaves the grid.
enum class DiffusionRole : std::uint8_t { Free, Fixed, Excluded };

SolveStats diffuse(GridField& field, const std::vector<DiffusionRole>& roles, glm::dvec3 h, double dtTimesD,
                   double tolerance, int maxIterations);

}  // namespace eikon::sim
