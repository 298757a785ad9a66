#include "sim/fluid/StencilOperator.h"

#include "sim/fluid/LaggedSlices.h"

#include <tbb/parallel_for.h>

namespace eikon::sim {

double SevenPointOperator::applyAndDot(const std::vector<double>& x, std::vector<double>& y) const {
    return sumOverSlices(*this, [&](int k) {
        double partial = 0.0;
        for (std::size_t c = index(0, 0, k), end = index(0, 0, k + 1); c < end; ++c) {
            y[c] = diag[c] == 0.0 ? 0.0 : diag[c] * x[c] - neighbourSum(x, c);
            partial += x[c] * y[c];
        }
        return partial;
    });
}

void SevenPointOperator::residual(const std::vector<double>& b, const std::vector<double>& x,
                                  std::vector<double>& r) const {
    forEachSlice(*this, [&](int k) {
        for (int j = 0; j < size.y; ++j)
            for (int i = 0; i < size.x; ++i) {
                const std::size_t c = index(i, j, k);
                r[c] = diag[c] == 0.0 ? 0.0 : b[c] - (diag[c] * x[c] - neighbourSum(x, c));
            }
    });
}

void SevenPointOperator::residualAfterSweep(const std::vector<double>& b, const std::vector<double>& x,
                                            std::vector<double>& r, int colour) const {
    forEachSlice(*this, [&](int k) {
        for (int j = 0; j < size.y; ++j)
            for (int i = 0; i < size.x; ++i) {
                const std::size_t c = index(i, j, k);
                r[c] = ((i + j + k + colour) & 1) != 0 || diag[c] == 0.0
                           ? 0.0
                           : b[c] - (diag[c] * x[c] - neighbourSum(x, c));
            }
    });
}

bool SevenPointOperator::passesInParallel() const { return cellCount() >= kSerialSliceCells; }

void SevenPointOperator::relaxSlice(const std::vector<double>& b, std::vector<double>& x, int k, int colour) const {
    for (int j = 0; j < size.y; ++j)
        for (int i = (j + k + colour) & 1; i < size.x; i += 2) {
            const std::size_t c = index(i, j, k);
            if (diag[c] != 0.0) x[c] = (b[c] + neighbourSum(x, c)) / diag[c];
        }
}

void SevenPointOperator::relaxBothColours(const std::vector<double>& b, std::vector<double>& x, int first) const {
    lagSecondPassBySlice(
        size.z, passesInParallel(), 0.0,
        [&](int k) {
            relaxSlice(b, x, k, first);
            return 0.0;
        },
        [&](int k) {
            relaxSlice(b, x, k, 1 - first);
            return 0.0;
        },
        std::plus<>());
}

void SevenPointOperator::relaxBothColoursFromZero(const std::vector<double>& b, std::vector<double>& x) const {
    lagSecondPassBySlice(
        size.z, passesInParallel(), 0.0,
        [&](int k) {
            for (int j = 0; j < size.y; ++j)
                for (int i = 0; i < size.x; ++i) {
                    const std::size_t c = index(i, j, k);
                    x[c] = ((i + j + k) & 1) == 0 && diag[c] != 0.0 ? b[c] / diag[c] : 0.0;
                }
            return 0.0;
        },
        [&](int k) {
            relaxSlice(b, x, k, 1);
            return 0.0;
        },
        std::plus<>());
}

double SevenPointOperator::relaxBothColoursAndDot(const std::vector<double>& b, std::vector<double>& x,
                                                  int first) const {
    return lagSecondPassBySlice(
        size.z, passesInParallel(), 0.0,
        [&](int k) {
            relaxSlice(b, x, k, first);
            return 0.0;
        },
        [&](int k) {
            relaxSlice(b, x, k, 1 - first);
            double partial = 0.0;
            for (std::size_t c = index(0, 0, k), end = index(0, 0, k + 1); c < end; ++c) partial += b[c] * x[c];
            return partial;
        },
        std::plus<>());
}

SevenPointOperator poissonOperator(glm::ivec3 size, glm::dvec3 h, const std::vector<std::uint8_t>& active,
                                   const bool openFaces[6]) {
    SevenPointOperator op;
    op.size = size;
    op.weight = 1.0 / (h * h);
    op.diag.assign(active.size(), 0.0);
    op.coupled.assign(active.size(), 0);
    tbb::parallel_for(0, size.z, [&](int k) {
        for (int j = 0; j < size.y; ++j)
            for (int i = 0; i < size.x; ++i) {
                const std::size_t c = op.index(i, j, k);
                if (!active[c]) continue;
                const glm::ivec3 cell(i, j, k);
                for (int axis = 0; axis < 3; ++axis)
                    for (int side = 0; side < 2; ++side) {
                        glm::ivec3 n = cell;
                        n[axis] += side == 0 ? -1 : 1;
                        if (n[axis] < 0 || n[axis] >= size[axis]) {
                            if (openFaces[2 * axis + side]) op.diag[c] += op.weight[axis];
                        } else if (active[op.index(n.x, n.y, n.z)]) {
                            op.diag[c] += op.weight[axis];
                            op.coupled[c] |= SevenPointOperator::bit(axis, side);
                        }
                    }
            }
    });
    return op;
}

}  // namespace eikon::sim
