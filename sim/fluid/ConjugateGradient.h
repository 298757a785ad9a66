// Preconditioned conjugate gradients on a SevenPointOperator
// ([Saad03] Alg. 9.1; [McAdams10] Alg. 2, with its multigrid V-cycle as the
// preconditioner).
#pragma once

#include "sim/fluid/StencilOperator.h"

#include <functional>
#include <vector>

namespace eikon::sim {

struct SolveStats {
    int iterations = 0;
    double relativeResidual = 0.0;  // max|b − A x| / max|b| at the end
};

// z ≈ M⁻¹ r, returning r · z (which CG needs next, so a pointwise
// preconditioner computes it in the same pass); M must be symmetric positive
// definite for CG to converge.
using Preconditioner = std::function<double(const std::vector<double>& r, std::vector<double>& z)>;

// The vectors CG works in, kept by the caller between solves so that a solve
// allocates nothing once they have their size.
struct CgWorkspace {
    std::vector<double> r, z, q, p;
};

// Solves A x = b from the x given, until max|r| <= tolerance · max|b| or
// maxIterations. With `singular` (a pure-Neumann problem whose null space is
// the constants over the active cells), b must have zero mean over them and
// residuals and preconditioned residuals are kept so.
SolveStats conjugateGradient(const SevenPointOperator& a, const std::vector<double>& b, std::vector<double>& x,
                             const Preconditioner& preconditioner, double tolerance, int maxIterations, bool singular,
                             CgWorkspace& work);

// The Jacobi preconditioner z = r / diag (0 off the unknowns).
Preconditioner jacobiPreconditioner(const SevenPointOperator& a);

}  // namespace eikon::sim
