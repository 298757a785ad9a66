// Implicit diffusion, ∂φ/∂t = D ∇²φ by backward Euler ([Stam99] §2.3):
// (I + Δt·D·L) φⁿ⁺¹ = φⁿ with L the positive seven-point Laplacian,
// unconditionally stable for any Δt·D/h². Solved for the increment
// δ = φⁿ⁺¹ − φⁿ, so the tolerance is relative to the change, not
// to the (possibly large) values: by red–black Gauss–Seidel when Δt·D/h² is
// small enough that it contracts fast (GaussSeidelIteration.h), by
// Jacobi-preconditioned conjugate gradients otherwise.
#pragma once

#include "sim/fluid/ConjugateGradient.h"
#include "sim/field/GridField.h"

#include <cstdint>
#include <vector>

namespace eikon::sim {

// How a sample takes part: Free samples diffuse; Fixed ones keep their value
// and act as Dirichlet neighbours (a held temperature, a wall velocity);
// Excluded ones (inside solids) neither change nor exchange anything.
// Edges of the lattice are Neumann: no flux leaves the grid.
enum class DiffusionRole : std::uint8_t { Free, Fixed, Excluded };

// The Jacobi contraction per sweep under which red–black Gauss–Seidel
// reaches the tolerance in fewer bytes moved than CG.
constexpr double kGaussSeidelBelow = 0.5;

// The operator I + Δt·D·L of a lattice with these roles: a Free sample is an
// unknown coupled to its Free neighbours, its diagonal gaining the weight of
// every neighbour it exchanges with (Free or Fixed); Fixed and Excluded
// samples are no unknowns; the lattice's edges are Neumann. Weights are 0
// until a solve sets Δt·D/h² (SevenPointOperator::setWeight).
SevenPointOperator diffusionOperator(glm::ivec3 size, const std::vector<DiffusionRole>& roles);

// Backward-Euler diffusion of the fields of one lattice with fixed roles. The
// operator's structure depends only on the roles, so it is built once; a solve
// only retabulates the diagonal when Δt·D/h² changes, and reuses its scratch.
// Rebuild it when the roles change (new solids, held cells).
class ImplicitDiffusion {
public:
    ImplicitDiffusion() = default;
    ImplicitDiffusion(glm::ivec3 size, const std::vector<DiffusionRole>& roles);

    SolveStats diffuse(GridField& field, glm::dvec3 h, double dtTimesD, double tolerance, int maxIterations);

private:
    // Coupled bits and diagonal classes fixed by the roles (a held or
    // excluded sample is no unknown); the weights follow Δt·D/h².
    SevenPointOperator a_;
    std::vector<double> rhs_, increment_;
    CgWorkspace work_;
};

}  // namespace eikon::sim
