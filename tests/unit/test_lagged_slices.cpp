// The lagged red–black sweep (LaggedSlices.h) gives bit for bit what two
// half-sweeps run one after the other give, on lattices small enough to run
// serially and large enough to be cut into chunks of uneven length, with
// inactive cells.
#include "sim/fluid/LaggedSlices.h"
#include "sim/fluid/StencilOperator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <random>
#include <vector>

namespace eikon::sim {
namespace {

// The Gauss–Seidel half-sweep over one colour, the plain way.
void halfSweep(const SevenPointOperator& op, const std::vector<double>& b, std::vector<double>& x, int colour) {
    for (int k = 0; k < op.size.z; ++k)
        for (int j = 0; j < op.size.y; ++j)
            for (int i = 0; i < op.size.x; ++i) {
                const std::size_t c = op.index(i, j, k);
                if (((i + j + k) & 1) == colour && op.isUnknown(c))
                    x[c] = (b[c] + op.neighbourSum(x, c)) * op.inverseDiagonal(c);
            }
}

SevenPointOperator operatorWithObstacle(glm::ivec3 size) {
    std::vector<std::uint8_t> active(static_cast<std::size_t>(size.x) * size.y * size.z, 1);
    const SevenPointOperator shape = [&] {
        SevenPointOperator s;
        s.size = size;
        return s;
    }();
    for (int k = 0; k < size.z; ++k)
        for (int j = 0; j < size.y; ++j)
            for (int i = 0; i < size.x; ++i)
                if ((i - size.x / 2) * (i - size.x / 2) + (j - size.y / 3) * (j - size.y / 3) < 9)
                    active[shape.index(i, j, k)] = 0;
    const bool open[6] = {false, false, false, true, false, false};
    return poissonOperator(size, glm::dvec3(0.1, 0.2, 0.15), active, open);
}

void expectSameAsTwoHalfSweeps(glm::ivec3 size) {
    SCOPED_TRACE(testing::Message() << size.x << "x" << size.y << "x" << size.z);
    const SevenPointOperator op = operatorWithObstacle(size);
    std::mt19937 rng(11);
    std::normal_distribution<double> normal;
    std::vector<double> b(op.cellCount()), start(op.cellCount());
    for (std::size_t c = 0; c < b.size(); ++c) {
        b[c] = normal(rng);
        start[c] = op.isUnknown(c) ? normal(rng) : 0.0;
    }
    for (int first = 0; first < 2; ++first) {
        std::vector<double> expected = start, lagged = start;
        halfSweep(op, b, expected, first);
        halfSweep(op, b, expected, 1 - first);
        op.relaxBothColours(b, lagged, first);
        EXPECT_EQ(lagged, expected) << "first colour " << first;

        std::vector<double> withDot = start;
        const double dot = op.relaxBothColoursAndDot(b, withDot, first);
        EXPECT_EQ(withDot, expected);
        double expectedDot = 0.0;
        for (std::size_t c = 0; c < b.size(); ++c) expectedDot += b[c] * expected[c];
        EXPECT_NEAR(dot, expectedDot, 1e-12 * op.cellCount());
    }
    std::vector<double> expected(op.cellCount(), 0.0), fromZero = start;
    halfSweep(op, b, expected, 0);
    halfSweep(op, b, expected, 1);
    op.relaxBothColoursFromZero(b, fromZero);
    EXPECT_EQ(fromZero, expected);
}

TEST(LaggedSlices, SerialSweepMatchesTwoHalfSweeps) {
    expectSameAsTwoHalfSweeps(glm::ivec3(7, 6, 5));
    expectSameAsTwoHalfSweeps(glm::ivec3(9, 8, 1));
    expectSameAsTwoHalfSweeps(glm::ivec3(9, 8, 2));
}

TEST(LaggedSlices, ChunkedSweepMatchesTwoHalfSweeps) {
    expectSameAsTwoHalfSweeps(glm::ivec3(24, 20, 40));   // chunks of 20 slices or fewer
    expectSameAsTwoHalfSweeps(glm::ivec3(33, 31, 67));   // uneven chunks
    expectSameAsTwoHalfSweeps(glm::ivec3(130, 130, 1));  // one slice, many cells
}

// Whatever the slice count, every slice's first and second pass run once,
// the second after the first pass of the slice and of both its neighbours.
TEST(LaggedSlices, EverySliceRunsBothPassesOnceInOrder) {
    for (int slices : {1, 2, 3, 16, 17, 31, 32, 33, 100}) {
        std::vector<std::atomic<int>> firstDone(static_cast<std::size_t>(slices));
        std::vector<std::atomic<int>> secondDone(static_cast<std::size_t>(slices));
        std::vector<std::atomic<int>> secondTooEarly(static_cast<std::size_t>(slices));
        const double count = lagSecondPassBySlice(
            slices, true, 0.0,
            [&](int k) {
                ++firstDone[k];
                return 1.0;
            },
            [&](int k) {
                for (int n = std::max(k - 1, 0); n <= std::min(k + 1, slices - 1); ++n)
                    if (firstDone[n] != 1) secondTooEarly[k] = 1;
                ++secondDone[k];
                return 1.0;
            },
            [](double u, double v) { return u + v; });
        EXPECT_EQ(count, 2.0 * slices);
        for (int k = 0; k < slices; ++k) {
            EXPECT_EQ(firstDone[k], 1) << slices << " slices, slice " << k;
            EXPECT_EQ(secondDone[k], 1) << slices << " slices, slice " << k;
            EXPECT_EQ(secondTooEarly[k], 0) << slices << " slices, slice " << k;
        }
    }
}

}  // namespace
}  // namespace eikon::sim
