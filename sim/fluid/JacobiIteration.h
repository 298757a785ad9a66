// Jacobi iteration (Saad, "Iterative Methods for Sparse Linear Systems",
// §4.1): x ← D⁻¹ (b + N x), with D the diagonal and N the couplings of a
// seven-point operator. For a strictly diagonally dominant A, such as the
// backward-Euler diffusion matrix I + Δt·D·L, the error contracts by at
// least ρ = max_c Σ_n w / diag_c per sweep. A sweep reads and writes a
// quarter of what a conjugate-gradient step does (no dot products, no
// search direction), so when ρ is small — diffusion over a time step much
// shorter than a cell's diffusion time — it reaches a tolerance for less
// than CG does.
#pragma once

#include "sim/fluid/ConjugateGradient.h"

#include <vector>

namespace eikon::sim {

// Solves A x = b from the x given, until max|b − A x| <= tolerance · max|b|
// or maxIterations sweeps; `next` is scratch. The residual is that of the
// iterate before the last sweep (r = D (x_new − x_old)), so the x returned is
// at least that accurate.
SolveStats jacobiIteration(const SevenPointOperator& a, const std::vector<double>& b, std::vector<double>& x,
                           std::vector<double>& next, double tolerance, int maxIterations);

}  // namespace eikon::sim
