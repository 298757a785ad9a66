// Implicit diffusion of sim/fluid/Diffusion.h on the GPU ([Stam99] §2.3):
// (I + Δt·D·L) φⁿ⁺¹ = φⁿ by backward Euler, solved for the increment
// δ = φⁿ⁺¹ − φⁿ in float64 from the float32 field: by red–black Gauss–Seidel
// (GaussSeidelIteration.h: one readback of max|r| per sweep, 8 bytes) when
// Δt·D/h² is small enough that it contracts fast, by Jacobi-preconditioned
// conjugate gradients (GpuConjugateGradient.h) otherwise. A field with
// nothing to diffuse (max|b| = 0: uniform, for one) returns at once with zero
// iterations, unchanged.
#pragma once

#include "sim/fluid/Diffusion.h"
#include "sim/gpu/GpuConjugateGradient.h"
#include "sim/gpu/GpuField.h"
#include "sim/gpu/GpuReduction.h"
#include "sim/gpu/GpuStencilOperator.h"

#include <memory>
#include <vector>

namespace eikon::sim::gpu {

class GpuDiffusion {
public:
    GpuDiffusion() = default;
    // The roles of the samples of a size-shaped lattice (DiffusionRole); rebuild when they change.
    GpuDiffusion(glm::ivec3 size, const std::vector<DiffusionRole>& roles);

    // As ImplicitDiffusion::diffuse, in place on the float field.
    SolveStats diffuse(GpuField& field, glm::dvec3 h, double dtTimesD, double tolerance, int maxIterations);

    // What the last diffuse() read back from the GPU (its stopping tests).
    std::size_t bytesReadBack() const { return bytesReadBack_; }

private:
    // GaussSeidelIteration.h's redBlackGaussSeidel on rhs_ into increment_.
    SolveStats gaussSeidel(double tolerance, int maxIterations);
    // The increment's half-sweep over `colour`, keeping the residuals met in residual_.
    void relax(int colour, bool fromZero);
    // z = r / diag
    void jacobi(const gl::Buffer& r, const gl::Buffer& z);

    GpuStencilOperator a_;
    std::unique_ptr<GpuReduction> reduction_;
    std::unique_ptr<GpuConjugateGradient> cg_;  // made on the first solve that needs it
    gl::Buffer rhs_, increment_;
    gl::Buffer residual_;  // the residuals a Gauss–Seidel sweep meets; made on the first such solve
    gl::Program rhsPass_, gaussSeidel_, jacobi_, addIncrement_;
    std::size_t bytesReadBack_ = 0;
};

}  // namespace eikon::sim::gpu
