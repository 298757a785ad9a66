// A geometric multigrid V-cycle on the cell-centred pressure Poisson problem,
// used as the preconditioner of conjugate gradients ([McAdams10] §3–4):
// coarse levels rediscretise the operator at 2h, a coarse cell is active when
// any of its children is; trilinear prolongation P and restriction
// R = Pᵀ / 2^d, red–black Gauss–Seidel smoothing in the order (red, black)
// before and (black, red) after the coarse correction, so the cycle is a
// symmetric operator as CG requires.
#pragma once

#include "sim/fluid/StencilOperator.h"

#include <array>
#include <cstdint>
#include <vector>

namespace eikon::sim {

constexpr int kSmoothingSweeps = 2;  // red–black pairs before and after the coarse correction
constexpr int kMinCoarsenSize = 4;   // an axis shorter than this is not coarsened

class MultigridPreconditioner {
public:
    // The fine operator is poissonOperator(size, h, active, openFaces).
    MultigridPreconditioner(glm::ivec3 size, glm::dvec3 h, const std::vector<std::uint8_t>& active,
                            const bool openFaces[6]);

    const SevenPointOperator& fineOperator() const { return levels_.front().op; }
    int levelCount() const { return static_cast<int>(levels_.size()); }

    // z = V-cycle(r) from a zero initial guess. Uses internal scratch: one call at a time.
    // Returns r · z, which CG needs next, from the cycle's last pass.
    double apply(const std::vector<double>& r, std::vector<double>& z) const;

private:
    // Cell-centred linear interpolation along one axis from n_coarse to n_fine
    // cells: fine cell f blends its parent f/2 (¾) and the parent's neighbour
    // on f's side (¼, clamped at the ends). An axis too short to coarsen maps
    // cell to cell.
    struct AxisTransfer {
        std::vector<int> parent, neighbour;          // per fine cell
        double parentWeight = 0.75;                  // ½ and ½ on an axis that is not coarsened
        double neighbourWeight = 0.25;
        std::vector<int> firstChild;                 // per coarse cell: first fine cell of its restriction support
        std::vector<std::array<double, 4>> weights;  // per coarse cell: Pᵀ weights of fine cells firstChild + 0..3
    };
    struct Level {
        SevenPointOperator op;
        std::array<AxisTransfer, 3> toCoarser;  // empty on the coarsest level
        double restrictionScale = 1.0;          // 1 / 2^(coarsened axes)
        mutable std::vector<double> x, b;  // the coarse levels' unknowns and right-hand sides
        mutable std::vector<double> r;     // the residual restricted to the next level
    };

    static AxisTransfer makeTransfer(int fine, bool coarsen);
    // x = V-cycle(b) on level l (the finest level works on the caller's
    // vectors); returns b · x.
    double vcycle(std::size_t level, const std::vector<double>& b, std::vector<double>& x) const;
    void restrictResidual(const Level& fine, const Level& coarse) const;
    // x (fine) += P · coarse.x on fine slice k
    void prolongAndAddSlice(const Level& coarse, const Level& fine, std::vector<double>& x, int k) const;

    std::vector<Level> levels_;
};

}  // namespace eikon::sim
