// The multigrid V-cycle preconditioner of sim/fluid/Multigrid.h on the GPU
// ([McAdams10] §3–4): the same hierarchy (each coarse level rediscretised at
// 2h by poissonOperator, a coarse cell active when any child is, an axis
// under 4 cells not coarsened), the same transfers and the same smoothing:
// red–black Gauss–Seidel, kSmoothingSweeps sweeps (red, black) before and
// (black, red) after the coarse correction, and symmetric sweeps on the
// coarsest level, so the cycle is a symmetric operator as CG requires.
//
// The levels are float32. A preconditioner need not be exact: the V-cycle
// only has to approximate A⁻¹ (it contracts the error by ~0.1), and CG, whose
// vectors and residual are float64, corrects what it misses, so float32
// (relative rounding ~1e-7, far below that contraction) changes the
// iteration count little while halving the bytes every smoothing pass moves.
// Its rounding makes the cycle symmetric to ~1e-6 rather than exactly, which
// cost CG no iteration against the float64 CPU cycle, at 1e-6 and at 1e-12
// (tests/integration/test_gpu_linear_solvers.cpp measures both).
#pragma once

#include "sim/gpu/GpuStencilOperator.h"

#include <cstdint>
#include <vector>

namespace eikon::sim::gpu {

class GpuMultigrid {
public:
    // The fine operator is poissonOperator(size, h, active, openFaces).
    GpuMultigrid(glm::ivec3 size, glm::dvec3 h, const std::vector<std::uint8_t>& active, const bool openFaces[6]);

    // The finest level's operator (the Poisson matrix CG solves).
    const GpuStencilOperator& fineOperator() const { return levels_.front().op; }
    int levelCount() const { return static_cast<int>(levels_.size()); }
    // Compute passes per apply().
    int dispatchesPerCycle() const;

    // z = V-cycle(r) from a zero initial guess; r and z float64 vectors of
    // the fine lattice, z 0 off the unknowns.
    void apply(const gl::Buffer& r, const gl::Buffer& z) const;

private:
    struct Level {
        GpuStencilOperator op;
        glm::ivec3 coarsened{0};  // per axis, 1 where the next level halves it
        float restrictionScale = 1.0f;  // 1 / 2^(coarsened axes)
        gl::Buffer x, b;  // float32 unknowns and right-hand side
        gl::Buffer r;     // the residual restricted to the next level
    };

    // x = V-cycle(b) on level l.
    void vcycle(std::size_t level) const;
    // A red–black half-sweep over `colour`; fromZero: from x = 0 (the other colour is cleared).
    void relax(const Level& level, int colour, bool fromZero) const;
    void restrictResidual(const Level& fine, const Level& coarse) const;
    void prolongAndAdd(const Level& coarse, const Level& fine) const;

    std::vector<Level> levels_;
    gl::Program smooth_, residual_, coarsest_, restrict_, prolong_, narrow_, widen_;
};

}  // namespace eikon::sim::gpu
