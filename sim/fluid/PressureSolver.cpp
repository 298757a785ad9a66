#include "sim/fluid/PressureSolver.h"

#include <tbb/parallel_for.h>

namespace eikon::sim {

PressureSolver::PressureSolver(const FluidDomain& domain, glm::dvec3 h)
    : domain_(domain),
      multigrid_(domain.cells, h, domain.fluidCells(), domain.openFaces().data()),
      singular_(!domain.anyOpenFace()) {}

SolveStats PressureSolver::project(MacGrid& mac, GridField& pressure, double tolerance, int maxIterations) const {
    const SevenPointOperator& a = multigrid_.fineOperator();
    const glm::ivec3 n = domain_.cells;
    std::vector<double>& rhs = rhs_;
    rhs.resize(a.cellCount());
    tbb::parallel_for(0, n.z, [&](int k) {
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                const std::size_t c = a.index(i, j, k);
                rhs[c] = a.isUnknown(c) ? -mac.divergence(i, j, k) : 0.0;
            }
    });
    if (singular_) a.removeMeanOverUnknowns(rhs);  // closed box: Σ∇·u = 0 up to rounding
    const SolveStats stats = conjugateGradient(
        a, rhs, pressure.values,
        [this](const std::vector<double>& r, std::vector<double>& z) { return multigrid_.apply(r, z); },
        tolerance,
        maxIterations, singular_, work_);

    // u −= ∇p on every free face; open faces see p = 0 outside.
    for (int axis = 0; axis < 3; ++axis) {
        GridField& u = mac.velocity[axis];
        const double invH = 1.0 / mac.h[axis];
        tbb::parallel_for(0, u.size.z, [&](int k) {
            for (int j = 0; j < u.size.y; ++j)
                for (int i = 0; i < u.size.x; ++i) {
                    if (domain_.faceIsFixed(axis, i, j, k)) {
                        u(i, j, k) = 0.0;
                        continue;
                    }
                    glm::ivec3 upper(i, j, k);
                    glm::ivec3 lower = upper;
                    lower[axis] -= 1;
                    const double pLower = lower[axis] >= 0 ? pressure(lower.x, lower.y, lower.z) : 0.0;
                    const double pUpper = upper[axis] < n[axis] ? pressure(upper.x, upper.y, upper.z) : 0.0;
                    u(i, j, k) -= (pUpper - pLower) * invH;
                }
        });
    }
    return stats;
}

}  // namespace eikon::sim
