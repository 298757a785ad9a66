#include "sim/fluid/StencilOperator.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cstddef>

namespace eikon::sim {

void SevenPointOperator::setWeight(glm::dvec3 w) {
    weight = w;
    for (int bits = 0; bits < kNotUnknown; ++bits) {
        double diag = identity;
        for (int axis = 0; axis < 3; ++axis)
            for (int side = 0; side < 2; ++side)
                if (bits & bit(axis, side)) diag += weight[axis];
        diagonalOfClass_[bits] = diag;
        inverseOfClass_[bits] = diag != 0.0 ? 1.0 / diag : 0.0;
    }
    diagonalOfClass_[kNotUnknown] = inverseOfClass_[kNotUnknown] = 0.0;
}

void SevenPointOperator::classifyRows() {
    plainRow.assign(static_cast<std::size_t>(size.y) * static_cast<std::size_t>(size.z), 0);
    if (size.x < 3) return;
    tbb::parallel_for(0, size.z, [&](int k) {
        for (int j = 0; j < size.y; ++j) {
            const std::size_t row = index(0, j, k);
            bool plain = true;
            for (int i = 1; plain && i + 1 < size.x; ++i)
                plain = coupled[row + i] == kAllCoupled && diagonalClass[row + i] == kAllCoupled;
            plainRow[static_cast<std::size_t>(j) + static_cast<std::size_t>(size.y) * k] = plain ? 1 : 0;
        }
    });
}

void SevenPointOperator::removeMeanOverUnknowns(std::vector<double>& values) const {
    using Range = tbb::blocked_range<std::size_t>;
    constexpr std::size_t kGrain = 4096;
    struct CountAndSum {
        double count = 0.0, sum = 0.0;
    };
    const CountAndSum total = tbb::parallel_deterministic_reduce(  // the same bits run after run
        Range(0, values.size(), kGrain), CountAndSum{},
        [&](const Range& r, CountAndSum partial) {
            for (std::size_t c = r.begin(); c < r.end(); ++c)
                if (isUnknown(c)) {
                    partial.count += 1.0;
                    partial.sum += values[c];
                }
            return partial;
        },
        [](CountAndSum u, CountAndSum v) { return CountAndSum{u.count + v.count, u.sum + v.sum}; });
    if (total.count == 0.0) return;
    const double mean = total.sum / total.count;
    tbb::parallel_for(Range(0, values.size(), kGrain), [&](const Range& r) {
        for (std::size_t c = r.begin(); c < r.end(); ++c) values[c] = isUnknown(c) ? values[c] - mean : 0.0;
    });
}

double SevenPointOperator::applyAndDot(const std::vector<double>& x, std::vector<double>& y) const {
    return sumOverSlices(*this, [&](int k) {
        double partial = 0.0;
        const double bulkDiag = bulkDiagonal();
        for (int j = 0; j < size.y; ++j)
            forRowCells(
                j, k, 0, 1,
                [&](std::size_t c) {
                    y[c] = isUnknown(c) ? diagonal(c) * x[c] - neighbourSum(x, c) : 0.0;
                    partial += x[c] * y[c];
                },
                [&](std::size_t c) {
                    y[c] = bulkDiag * x[c] - bulkNeighbourSum(x, c);
                    partial += x[c] * y[c];
                });
        return partial;
    });
}

void SevenPointOperator::residual(const std::vector<double>& b, const std::vector<double>& x,
                                  std::vector<double>& r) const {
    forEachSlice(*this, [&](int k) {
        for (std::size_t c = index(0, 0, k), end = index(0, 0, k + 1); c < end; ++c)
            r[c] = isUnknown(c) ? b[c] - (diagonal(c) * x[c] - neighbourSum(x, c)) : 0.0;
    });
}

void SevenPointOperator::residualSliceAfterSweep(const std::vector<double>& b, const std::vector<double>& x,
                                                 std::vector<double>& r, int k, int colour) const {
    const double bulkDiag = bulkDiagonal();
    for (int j = 0; j < size.y; ++j) {
        std::fill_n(r.begin() + static_cast<std::ptrdiff_t>(index(0, j, k)), size.x, 0.0);
        forRowCells(
            j, k, (j + k + colour) & 1, 2,
            [&](std::size_t c) {
                if (isUnknown(c)) r[c] = b[c] - (diagonal(c) * x[c] - neighbourSum(x, c));
            },
            [&](std::size_t c) { r[c] = b[c] - (bulkDiag * x[c] - bulkNeighbourSum(x, c)); });
    }
}

bool SevenPointOperator::passesInParallel() const { return cellCount() >= kSerialSliceCells; }

void SevenPointOperator::relaxSlice(const std::vector<double>& b, std::vector<double>& x, int k, int colour) const {
    const double bulkInverse = bulkInverseDiagonal();
    for (int j = 0; j < size.y; ++j)
        forRowCells(
            j, k, (j + k + colour) & 1, 2,
            [&](std::size_t c) {
                if (isUnknown(c)) x[c] = (b[c] + neighbourSum(x, c)) * inverseDiagonal(c);
            },
            [&](std::size_t c) { x[c] = (b[c] + bulkNeighbourSum(x, c)) * bulkInverse; });
}

void SevenPointOperator::relaxSliceFromZero(const std::vector<double>& b, std::vector<double>& x, int k) const {
    for (int j = 0; j < size.y; ++j)
        for (int i = 0; i < size.x; ++i) {
            const std::size_t c = index(i, j, k);
            x[c] = ((i + j + k) & 1) == 0 ? b[c] * inverseDiagonal(c) : 0.0;
        }
}

double SevenPointOperator::dotSlice(const std::vector<double>& b, const std::vector<double>& x, int k) const {
    double partial = 0.0;
    for (std::size_t c = index(0, 0, k), end = index(0, 0, k + 1); c < end; ++c) partial += b[c] * x[c];
    return partial;
}

SevenPointOperator poissonOperator(glm::ivec3 size, glm::dvec3 h, const std::vector<std::uint8_t>& active,
                                   const bool openFaces[6]) {
    SevenPointOperator op;
    op.size = size;
    op.diagonalClass.assign(active.size(), SevenPointOperator::kNotUnknown);
    op.coupled.assign(active.size(), 0);
    tbb::parallel_for(0, size.z, [&](int k) {
        for (int j = 0; j < size.y; ++j)
            for (int i = 0; i < size.x; ++i) {
                const std::size_t c = op.index(i, j, k);
                if (!active[c]) continue;
                const glm::ivec3 cell(i, j, k);
                std::uint8_t faces = 0;  // that add to the diagonal
                for (int axis = 0; axis < 3; ++axis)
                    for (int side = 0; side < 2; ++side) {
                        glm::ivec3 n = cell;
                        n[axis] += side == 0 ? -1 : 1;
                        if (n[axis] < 0 || n[axis] >= size[axis]) {
                            if (openFaces[2 * axis + side]) faces |= SevenPointOperator::bit(axis, side);
                        } else if (active[op.index(n.x, n.y, n.z)]) {
                            faces |= SevenPointOperator::bit(axis, side);
                            op.coupled[c] |= SevenPointOperator::bit(axis, side);
                        }
                    }
                // A fluid cell walled in on every side has a zero row: no unknown.
                if (faces != 0) op.diagonalClass[c] = faces;
            }
    });
    op.setWeight(1.0 / (h * h));
    op.classifyRows();
    return op;
}

}  // namespace eikon::sim
