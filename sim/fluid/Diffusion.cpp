#include "sim/fluid/Diffusion.h"

#include "sim/fluid/ParallelOps.h"

#include <tbb/parallel_for.h>

namespace eikon::sim {

SolveStats diffuse(GridField& field, const std::vector<DiffusionRole>& roles, glm::dvec3 h, double dtTimesD,
                   double tolerance, int maxIterations) {
    if (dtTimesD <= 0.0) return {};
    const glm::ivec3 n = field.size;
    SevenPointOperator a;
    a.size = n;
    a.weight = dtTimesD / (h * h);
    a.diag.assign(field.count(), 0.0);
    a.coupled.assign(field.count(), 0);
    std::vector<double> rhs(field.count(), 0.0);
    tbb::parallel_for(0, n.z, [&](int k) {
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                const std::size_t c = a.index(i, j, k);
                if (roles[c] != DiffusionRole::Free) continue;
                const glm::ivec3 cell(i, j, k);
                double diag = 1.0;
                double flux = 0.0;  // Σ w (φ_c − φ_n): −(Δt D ∇²φ)_c
                for (int axis = 0; axis < 3; ++axis)
                    for (int side = 0; side < 2; ++side) {
                        glm::ivec3 m = cell;
                        m[axis] += side == 0 ? -1 : 1;
                        if (m[axis] < 0 || m[axis] >= n[axis]) continue;
                        const std::size_t neighbour = a.index(m.x, m.y, m.z);
                        if (roles[neighbour] == DiffusionRole::Excluded) continue;
                        diag += a.weight[axis];
                        flux += a.weight[axis] * (field.values[c] - field.values[neighbour]);
                        if (roles[neighbour] == DiffusionRole::Free) a.coupled[c] |= SevenPointOperator::bit(axis, side);
                    }
                a.diag[c] = diag;
                rhs[c] = -flux;
            }
    });
    std::vector<double> increment(field.count(), 0.0);
    const SolveStats stats =
        conjugateGradient(a, rhs, increment, jacobiPreconditioner(a), tolerance, maxIterations, false);
    axpy(1.0, increment, field.values);
    return stats;
}

}  // namespace eikon::sim
