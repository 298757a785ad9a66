#include "sim/fluid/Multigrid.h"

#include "sim/fluid/ParallelOps.h"
#include "sim/fluid/WavefrontSlices.h"

#include <algorithm>

namespace eikon::sim {

MultigridPreconditioner::AxisTransfer MultigridPreconditioner::makeTransfer(int fine, bool coarsen) {
    AxisTransfer t;
    const int coarse = coarsen ? (fine + 1) / 2 : fine;
    if (!coarsen) t.parentWeight = t.neighbourWeight = 0.5;
    t.parent.resize(fine);
    t.neighbour.resize(fine);
    for (int f = 0; f < fine; ++f) {
        const int p = coarsen ? f / 2 : f;
        t.parent[f] = p;
        t.neighbour[f] = coarsen ? std::clamp(f % 2 == 0 ? p - 1 : p + 1, 0, coarse - 1) : p;
    }
    // Pᵀ: coarse cell C collects ¾ from each fine cell with parent C and ¼
    // from each whose neighbour is C; those fine cells lie in [2C − 1, 2C + 2].
    t.firstChild.resize(coarse);
    t.weights.resize(coarse);
    for (int c = 0; c < coarse; ++c) {
        const int first = coarsen ? 2 * c - 1 : c;
        t.firstChild[c] = first;
        for (int s = 0; s < 4; ++s) {
            const int f = first + s;
            double w = 0.0;
            if (f >= 0 && f < fine) {
                if (t.parent[f] == c) w += t.parentWeight;
                if (t.neighbour[f] == c) w += t.neighbourWeight;
            }
            t.weights[c][s] = w;
        }
    }
    return t;
}

MultigridPreconditioner::MultigridPreconditioner(glm::ivec3 size, glm::dvec3 h,
                                                 const std::vector<std::uint8_t>& active, const bool openFaces[6]) {
    std::vector<std::uint8_t> levelActive = active;
    while (true) {
        Level level;
        level.op = poissonOperator(size, h, levelActive, openFaces);
        if (!levels_.empty()) {  // the finest level's unknowns and right-hand side are the caller's
            level.x.assign(level.op.cellCount(), 0.0);
            level.b = level.x;
        }
        level.r.assign(level.op.cellCount(), 0.0);
        const bool coarsen[3] = {size.x >= kMinCoarsenSize, size.y >= kMinCoarsenSize, size.z >= kMinCoarsenSize};
        if (!coarsen[0] && !coarsen[1] && !coarsen[2]) {
            levels_.push_back(std::move(level));
            return;
        }
        glm::ivec3 coarseSize = size;
        for (int axis = 0; axis < 3; ++axis) {
            level.toCoarser[axis] = makeTransfer(size[axis], coarsen[axis]);
            if (coarsen[axis]) {
                coarseSize[axis] = (size[axis] + 1) / 2;
                h[axis] *= 2.0;
                level.restrictionScale *= 0.5;
            }
        }
        std::vector<std::uint8_t> coarseActive(static_cast<std::size_t>(coarseSize.x) * coarseSize.y * coarseSize.z, 0);
        const SevenPointOperator& op = level.op;
        for (int k = 0; k < size.z; ++k)
            for (int j = 0; j < size.y; ++j)
                for (int i = 0; i < size.x; ++i) {
                    if (!levelActive[op.index(i, j, k)]) continue;
                    const int ci = level.toCoarser[0].parent[i];
                    const int cj = level.toCoarser[1].parent[j];
                    const int ck = level.toCoarser[2].parent[k];
                    coarseActive[ci + static_cast<std::size_t>(coarseSize.x) * (cj + static_cast<std::size_t>(coarseSize.y) * ck)] = 1;
                }
        levels_.push_back(std::move(level));
        size = coarseSize;
        levelActive = std::move(coarseActive);
    }
}

double MultigridPreconditioner::apply(const std::vector<double>& r, std::vector<double>& z) const {
    z.resize(r.size());
    return vcycle(0, r, z);
}

double MultigridPreconditioner::vcycle(std::size_t l, const std::vector<double>& b, std::vector<double>& x) const {
    const Level& level = levels_[l];
    const SevenPointOperator& op = level.op;
    const bool parallel = op.passesInParallel();
    if (l + 1 == levels_.size()) {
        // Coarsest level: symmetric Gauss–Seidel sweeps from zero, colours
        // (0, 1, 1, 0), enough to cross it a few times.
        const int sweeps = 2 * std::max({op.size.x, op.size.y, op.size.z});
        std::fill(x.begin(), x.end(), 0.0);
        for (int s = 0; s < sweeps; ++s)
            runStagesAsWavefront(
                op.size.z, 4, parallel, 0.0,
                [&](int q, int k) {
                    op.relaxSlice(b, x, k, q == 0 || q == 3 ? 0 : 1);
                    return 0.0;
                },
                std::plus<>());
        return dot(b, x);
    }
    // Pre-smoothing from x = 0, colours (0, 1) per sweep, and the residual,
    // which the last half-sweep (colour 1) left on colour 0 only: one pass.
    constexpr int kPreStages = 2 * kSmoothingSweeps + 1;
    runStagesAsWavefront(
        op.size.z, kPreStages, parallel, 0.0,
        [&](int q, int k) {
            if (q == 0) {
                op.relaxSliceFromZero(b, x, k);
            } else if (q < kPreStages - 1) {
                op.relaxSlice(b, x, k, q % 2);
            } else {
                op.residualSliceAfterSweep(b, x, level.r, k, 0);
            }
            return 0.0;
        },
        std::plus<>());
    const Level& coarse = levels_[l + 1];
    restrictResidual(level, coarse);
    vcycle(l + 1, coarse.b, coarse.x);
    // The coarse correction and post-smoothing, colours (1, 0) per sweep so
    // that the cycle is symmetric, and b · x once a slice is final: one pass.
    constexpr int kPostStages = 1 + 2 * kSmoothingSweeps;
    return runStagesAsWavefront(
        op.size.z, kPostStages, parallel, 0.0,
        [&](int q, int k) {
            if (q == 0) {
                prolongAndAddSlice(coarse, level, x, k);
                return 0.0;
            }
            op.relaxSlice(b, x, k, q % 2);
            return q == kPostStages - 1 ? op.dotSlice(b, x, k) : 0.0;
        },
        std::plus<>())[kPostStages - 1];
}

void MultigridPreconditioner::restrictResidual(const Level& fine, const Level& coarse) const {
    const glm::ivec3 cs = coarse.op.size;
    const auto& tx = fine.toCoarser[0];
    const auto& ty = fine.toCoarser[1];
    const auto& tz = fine.toCoarser[2];
    forEachSlice(coarse.op, [&](int ck) {
        std::vector<double> blended(static_cast<std::size_t>(fine.op.size.x));
        for (int cj = 0; cj < cs.y; ++cj) {
            // Blend the (at most 4 × 4) fine rows feeding this coarse row with
            // their y–z weights, then restrict the blend along x: Pᵀ is separable.
            std::fill(blended.begin(), blended.end(), 0.0);
            for (int a = 0; a < 4; ++a) {
                const double wz = tz.weights[ck][a];
                if (wz == 0.0) continue;
                for (int b = 0; b < 4; ++b) {
                    const double wyz = wz * ty.weights[cj][b];
                    if (wyz == 0.0) continue;
                    const double* row = fine.r.data() + fine.op.index(0, ty.firstChild[cj] + b, tz.firstChild[ck] + a);
                    for (int fi = 0; fi < fine.op.size.x; ++fi) blended[fi] += wyz * row[fi];
                }
            }
            for (int ci = 0; ci < cs.x; ++ci) {
                const std::size_t c = coarse.op.index(ci, cj, ck);
                double s = 0.0;
                if (coarse.op.isUnknown(c)) {
                    for (int d = 0; d < 4; ++d) {
                        const double wx = tx.weights[ci][d];
                        if (wx != 0.0) s += wx * blended[tx.firstChild[ci] + d];
                    }
                }
                coarse.b[c] = fine.restrictionScale * s;
            }
        }
    });
}

void MultigridPreconditioner::prolongAndAddSlice(const Level& coarse, const Level& fine, std::vector<double>& x,
                                                 int k) const {
    const glm::ivec3 fs = fine.op.size;
    const auto& tx = fine.toCoarser[0];
    const auto& ty = fine.toCoarser[1];
    const auto& tz = fine.toCoarser[2];
    const int zs[2] = {tz.parent[k], tz.neighbour[k]};
    const double wzs[2] = {tz.parentWeight, tz.neighbourWeight};
    std::vector<double> blended(static_cast<std::size_t>(coarse.op.size.x));
    for (int j = 0; j < fs.y; ++j) {
        // Blend the 2 × 2 coarse rows this fine row interpolates with their
        // y–z weights, then interpolate the blend along x: P is separable.
        const int ys[2] = {ty.parent[j], ty.neighbour[j]};
        const double wys[2] = {ty.parentWeight, ty.neighbourWeight};
        const double* rows[4];
        double weights[4];
        for (int a = 0; a < 2; ++a)
            for (int b = 0; b < 2; ++b) {
                rows[2 * a + b] = coarse.x.data() + coarse.op.index(0, ys[b], zs[a]);
                weights[2 * a + b] = wzs[a] * wys[b];
            }
        for (int ci = 0; ci < coarse.op.size.x; ++ci)
            blended[ci] = weights[0] * rows[0][ci] + weights[1] * rows[1][ci] + weights[2] * rows[2][ci] +
                          weights[3] * rows[3][ci];
        for (int i = 0; i < fs.x; ++i) {
            const std::size_t f = fine.op.index(i, j, k);
            if (fine.op.isUnknown(f))
                x[f] += tx.parentWeight * blended[tx.parent[i]] + tx.neighbourWeight * blended[tx.neighbour[i]];
        }
    }
}

}  // namespace eikon::sim
