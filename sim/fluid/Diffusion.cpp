#include "sim/fluid/Diffusion.h"

#include "sim/fluid/GaussSeidelIteration.h"
#include "sim/fluid/ParallelOps.h"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace eikon::sim {

SevenPointOperator diffusionOperator(glm::ivec3 size, const std::vector<DiffusionRole>& roles) {
    SevenPointOperator a;
    a.size = size;
    a.identity = 1.0;
    a.diagonalClass.assign(roles.size(), SevenPointOperator::kNotUnknown);
    a.coupled.assign(roles.size(), 0);
    tbb::parallel_for(0, size.z, [&](int k) {
        for (int j = 0; j < size.y; ++j)
            for (int i = 0; i < size.x; ++i) {
                const std::size_t c = a.index(i, j, k);
                if (roles[c] != DiffusionRole::Free) continue;
                std::uint8_t exchanging = 0;
                const glm::ivec3 cell(i, j, k);
                for (int axis = 0; axis < 3; ++axis)
                    for (int side = 0; side < 2; ++side) {
                        glm::ivec3 m = cell;
                        m[axis] += side == 0 ? -1 : 1;
                        if (m[axis] < 0 || m[axis] >= size[axis]) continue;
                        const DiffusionRole role = roles[a.index(m.x, m.y, m.z)];
                        if (role == DiffusionRole::Excluded) continue;
                        exchanging |= SevenPointOperator::bit(axis, side);
                        if (role == DiffusionRole::Free) a.coupled[c] |= SevenPointOperator::bit(axis, side);
                    }
                a.diagonalClass[c] = exchanging;
            }
    });
    a.setWeight(glm::dvec3(0.0));
    return a;
}

ImplicitDiffusion::ImplicitDiffusion(glm::ivec3 size, const std::vector<DiffusionRole>& roles)
    : a_(diffusionOperator(size, roles)) {
    a_.classifyRows();
    increment_.assign(roles.size(), 0.0);
    rhs_.assign(roles.size(), 0.0);
}

SolveStats ImplicitDiffusion::diffuse(GridField& field, glm::dvec3 h, double dtTimesD, double tolerance,
                                      int maxIterations) {
    if (dtTimesD <= 0.0 || isUniform(field.values)) return {};  // a uniform field is steady: L φ = 0
    const glm::dvec3 weight = dtTimesD / (h * h);
    if (a_.weight != weight) a_.setWeight(weight);
    const glm::dvec3 w = a_.weight;
    const std::size_t sy = static_cast<std::size_t>(a_.size.x);
    const std::size_t sz = sy * static_cast<std::size_t>(a_.size.y);
    const std::vector<double>& phi = field.values;
    // rhs = −Σ w (φ_c − φ_n) over the exchanging neighbours: (Δt D ∇²φ)_c.
    const double bulkDiagonalWeight = a_.bulkDiagonal() - a_.identity;  // Σ w over all six faces
    tbb::parallel_for(0, a_.size.z, [&](int k) {
        for (int j = 0; j < a_.size.y; ++j)
            a_.forRowCells(
                j, k, 0, 1,
                [&](std::size_t c) {
                    const std::uint8_t bits = a_.diagonalClass[c];  // no face bits for a held or excluded sample
                    double flux = 0.0;
                    if (bits & SevenPointOperator::bit(0, 0)) flux += w.x * (phi[c] - phi[c - 1]);
                    if (bits & SevenPointOperator::bit(0, 1)) flux += w.x * (phi[c] - phi[c + 1]);
                    if (bits & SevenPointOperator::bit(1, 0)) flux += w.y * (phi[c] - phi[c - sy]);
                    if (bits & SevenPointOperator::bit(1, 1)) flux += w.y * (phi[c] - phi[c + sy]);
                    if (bits & SevenPointOperator::bit(2, 0)) flux += w.z * (phi[c] - phi[c - sz]);
                    if (bits & SevenPointOperator::bit(2, 1)) flux += w.z * (phi[c] - phi[c + sz]);
                    rhs_[c] = -flux;
                },
                [&](std::size_t c) { rhs_[c] = a_.bulkNeighbourSum(phi, c) - bulkDiagonalWeight * phi[c]; });
    });
    // Jacobi contracts the error by ρ <= 2Σw / (1 + 2Σw) per sweep and
    // red–black Gauss–Seidel by about ρ²; below kGaussSeidelBelow that
    // reaches the tolerance in fewer bytes moved than CG.
    const double coupling = 2.0 * (w.x + w.y + w.z);
    SolveStats stats;
    if (coupling / (1.0 + coupling) <= kGaussSeidelBelow) {
        stats = redBlackGaussSeidel(a_, rhs_, increment_, tolerance, maxIterations);
    } else {
        std::fill(increment_.begin(), increment_.end(), 0.0);
        stats = conjugateGradient(a_, rhs_, increment_, jacobiPreconditioner(a_), tolerance, maxIterations, false, work_);
    }
    axpy(1.0, increment_, field.values);
    return stats;
}

}  // namespace eikon::sim
