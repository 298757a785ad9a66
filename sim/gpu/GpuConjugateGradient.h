// Preconditioned conjugate gradients on the GPU ([Saad03] Alg. 9.1;
// [McAdams10] Alg. 2), as sim/fluid/ConjugateGradient.h: the same
// iteration, the same stopping test max|r| <= tolerance · max|b|, the same
// handling of the singular pure-Neumann case. The vectors are float64, so
// relative tolerances of 1e-8 stay reachable. The scalars stay on the GPU:
// reductions leave ρ = r · z and p · A p in result slots and the update
// passes compute α and β from them (shaders/sim/cg_update.comp). The host
// reads back max|b| and the first max|r| together (16 bytes), then max|r|
// once per iteration (8 bytes), for the stopping test.
#pragma once

#include "sim/fluid/ConjugateGradient.h"
#include "sim/gpu/GpuReduction.h"
#include "sim/gpu/GpuStencilOperator.h"

#include <cstddef>
#include <functional>

namespace eikon::sim::gpu {

class GpuConjugateGradient {
public:
    // z = M r on the GPU, both float64 vectors of the operator's lattice; M
    // symmetric positive definite, and z 0 off the unknowns.
    using Preconditioner = std::function<void(const gl::Buffer& r, const gl::Buffer& z)>;

    // Allocates the residual, search direction and A·p (which also holds the
    // preconditioned residual) for `shape`'s lattice.
    explicit GpuConjugateGradient(const GpuStencilOperator& shape);

    // Solves A x = b from the x given (float64 vectors, b 0 off the
    // unknowns), until max|r| <= tolerance · max|b| or maxIterations. With
    // `singular`, b must have zero mean over the unknowns, and residuals and
    // preconditioned residuals are kept so.
    SolveStats solve(const GpuStencilOperator& a, const gl::Buffer& b, gl::Buffer& x,
                     const Preconditioner& preconditioner, double tolerance, int maxIterations, bool singular);

    // values −= their mean over a's unknowns, 0 elsewhere; values must be 0 off the unknowns.
    void removeMeanOverUnknowns(const GpuStencilOperator& a, const gl::Buffer& values);

    // What the last solve read back from the GPU.
    std::size_t bytesReadBack() const { return bytesReadBack_; }

private:
    // The result slots.
    static constexpr int kRightHandSideNorm = 0;  // max|b|
    static constexpr int kResidualNorm = 1;       // max|r|: beside max|b|, so both come back in one read
    static constexpr int kCurvature = 2;          // p · A p
    static constexpr int kRho = 3;                // r · z, alternating with kRho + 1
    static constexpr int kSum = 5;                // a sum for removeMeanOverUnknowns

    // z = M r, its mean removed when singular, and ρ = r · z into slot rhoSlot.
    void precondition(const GpuStencilOperator& a, const Preconditioner& preconditioner, bool singular, int rhoSlot);
    double readResidualNorm();

    GpuReduction reduction_;
    gl::Buffer r_, p_, q_;
    gl::Program apply_, residual_, step_, direction_, removeMean_;
    std::size_t bytesReadBack_ = 0;
};

}  // namespace eikon::sim::gpu
