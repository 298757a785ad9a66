#include "sim/fluid/Diffusion.h"

#include "sim/fluid/GaussSeidelIteration.h"
#include "sim/fluid/ParallelOps.h"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace eikon::sim {

namespace {

constexpr double kGaussSeidelBelow = 0.5;  // Jacobi contraction per sweep under which Gauss–Seidel beats CG
constexpr std::uint8_t kNotFree = 64;  // the diagonal class of a held or excluded sample

}  // namespace

ImplicitDiffusion::ImplicitDiffusion(glm::ivec3 size, const std::vector<DiffusionRole>& roles)
    : diagonalClass_(roles.size(), kNotFree) {
    a_.size = size;
    a_.diag.assign(roles.size(), 0.0);
    a_.coupled.assign(roles.size(), 0);
    tbb::parallel_for(0, size.z, [&](int k) {
        for (int j = 0; j < size.y; ++j)
            for (int i = 0; i < size.x; ++i) {
                const std::size_t c = a_.index(i, j, k);
                if (roles[c] != DiffusionRole::Free) continue;
                diagonalClass_[c] = 0;
                const glm::ivec3 cell(i, j, k);
                for (int axis = 0; axis < 3; ++axis)
                    for (int side = 0; side < 2; ++side) {
                        glm::ivec3 m = cell;
                        m[axis] += side == 0 ? -1 : 1;
                        if (m[axis] < 0 || m[axis] >= size[axis]) continue;
                        const DiffusionRole role = roles[a_.index(m.x, m.y, m.z)];
                        if (role == DiffusionRole::Excluded) continue;
                        diagonalClass_[c] |= SevenPointOperator::bit(axis, side);
                        if (role == DiffusionRole::Free) a_.coupled[c] |= SevenPointOperator::bit(axis, side);
                    }
            }
    });
    increment_.assign(roles.size(), 0.0);
    rhs_.assign(roles.size(), 0.0);
}

void ImplicitDiffusion::setWeight(glm::dvec3 weight) {
    if (a_.weight == weight && !diagonal_.empty()) return;
    a_.weight = weight;
    diagonal_.assign(kNotFree + 1, 0.0);  // the class of a held or excluded sample keeps 0
    inverseDiagonal_.assign(kNotFree + 1, 0.0);
    for (std::uint8_t bits = 0; bits < kNotFree; ++bits) {
        double diag = 1.0;
        for (int axis = 0; axis < 3; ++axis)
            for (int side = 0; side < 2; ++side)
                if (bits & SevenPointOperator::bit(axis, side)) diag += weight[axis];
        diagonal_[bits] = diag;
        inverseDiagonal_[bits] = 1.0 / diag;
    }
    operatorDiagonalSet_ = false;
}

void ImplicitDiffusion::setOperatorDiagonal() {
    if (operatorDiagonalSet_) return;
    tbb::parallel_for(0, a_.size.z, [&](int k) {
        for (std::size_t c = a_.index(0, 0, k), end = a_.index(0, 0, k + 1); c < end; ++c)
            a_.diag[c] = diagonal_[diagonalClass_[c]];
    });
    operatorDiagonalSet_ = true;
}

SolveStats ImplicitDiffusion::diffuse(GridField& field, glm::dvec3 h, double dtTimesD, double tolerance,
                                      int maxIterations) {
    if (dtTimesD <= 0.0 || isUniform(field.values)) return {};  // a uniform field is steady: L φ = 0
    setWeight(dtTimesD / (h * h));
    const glm::dvec3 w = a_.weight;
    const std::size_t sy = static_cast<std::size_t>(a_.size.x);
    const std::size_t sz = sy * static_cast<std::size_t>(a_.size.y);
    const std::vector<double>& phi = field.values;
    // rhs = −Σ w (φ_c − φ_n) over the exchanging neighbours: (Δt D ∇²φ)_c.
    tbb::parallel_for(0, a_.size.z, [&](int k) {
        for (std::size_t c = a_.index(0, 0, k), end = a_.index(0, 0, k + 1); c < end; ++c) {
            const std::uint8_t bits = diagonalClass_[c];  // no axis bits for a held or excluded sample
            double flux = 0.0;
            if (bits & SevenPointOperator::bit(0, 0)) flux += w.x * (phi[c] - phi[c - 1]);
            if (bits & SevenPointOperator::bit(0, 1)) flux += w.x * (phi[c] - phi[c + 1]);
            if (bits & SevenPointOperator::bit(1, 0)) flux += w.y * (phi[c] - phi[c - sy]);
            if (bits & SevenPointOperator::bit(1, 1)) flux += w.y * (phi[c] - phi[c + sy]);
            if (bits & SevenPointOperator::bit(2, 0)) flux += w.z * (phi[c] - phi[c - sz]);
            if (bits & SevenPointOperator::bit(2, 1)) flux += w.z * (phi[c] - phi[c + sz]);
            rhs_[c] = -flux;
        }
    });
    // Jacobi contracts the error by ρ <= 2Σw / (1 + 2Σw) per sweep and
    // red–black Gauss–Seidel by about ρ²; below kGaussSeidelBelow that
    // reaches the tolerance in fewer bytes moved than CG.
    const double coupling = 2.0 * (w.x + w.y + w.z);
    SolveStats stats;
    if (coupling / (1.0 + coupling) <= kGaussSeidelBelow) {
        const auto diagonalOf = [&](std::size_t c) {
            const std::uint8_t sampleClass = diagonalClass_[c];
            return DiagonalEntry{diagonal_[sampleClass], inverseDiagonal_[sampleClass]};
        };
        stats = redBlackGaussSeidel(a_, diagonalOf, rhs_, increment_, tolerance, maxIterations);
    } else {
        setOperatorDiagonal();
        std::fill(increment_.begin(), increment_.end(), 0.0);
        stats = conjugateGradient(a_, rhs_, increment_, jacobiPreconditioner(a_), tolerance, maxIterations, false, work_);
    }
    axpy(1.0, increment_, field.values);
    return stats;
}

}  // namespace eikon::sim
