// The pressure projection of sim/fluid/PressureSolver.h on the GPU
// ([Bridson15] ch. 5; [Stam99] §2): L p = −∇·u* on the fluid cells, by
// conjugate gradients preconditioned with the multigrid V-cycle
// ([McAdams10]), then u = u* − ∇p on the free faces and 0 on the fixed
// ones. The right-hand side, the Krylov vectors and the solution are float64;
// the velocity and the pressure written out are float32 fields.
#pragma once

#include "sim/fluid/Boundaries.h"
#include "sim/fluid/ConjugateGradient.h"
#include "sim/gpu/GpuConjugateGradient.h"
#include "sim/gpu/GpuField.h"
#include "sim/gpu/GpuMultigrid.h"

#include <array>

namespace eikon::sim::gpu {

class GpuPressureSolver {
public:
    // Builds the multigrid hierarchy for this domain; rebuild when solids change.
    GpuPressureSolver(const FluidDomain& domain, glm::dvec3 h);

    // As PressureSolver::project: projects `velocity` (the MAC components
    // u, v, w); `pressure` (a cell-centred field) receives p. The initial
    // guess is the float64 solution of the previous call (0 on the first),
    // as the CPU solver starts from the last pressure. Stops at
    // max|∇·u| <= tolerance · max|∇·u*| or maxIterations.
    SolveStats project(std::array<GpuField, 3>& velocity, GpuField& pressure, double tolerance, int maxIterations);

    // Takes `pressure` (float32) as the next initial guess, as the CPU solver
    // starts from the pressure it is handed.
    void setInitialGuess(const GpuField& pressure);

    const GpuMultigrid& multigrid() const { return multigrid_; }
    // What the last projection read back from the GPU (CG's stopping tests).
    std::size_t bytesReadBack() const { return cg_.bytesReadBack(); }

private:
    glm::ivec3 cells_;
    glm::dvec3 h_;
    GLuint openFaces_ = 0;  // bit 2·axis + side
    bool singular_;         // no open face: p is determined up to a constant
    GpuMultigrid multigrid_;
    GpuConjugateGradient cg_;
    gl::Buffer solid_;     // per cell, 1 = solid (uint)
    gl::Buffer rhs_;       // −∇·u* on the unknowns
    gl::Buffer solution_;  // p, float64, kept as the next initial guess
    gl::Program divergence_, gradient_, widen_;
};

}  // namespace eikon::sim::gpu
