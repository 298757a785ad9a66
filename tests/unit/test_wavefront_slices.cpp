// Stages run as a wavefront over slices (WavefrontSlices.h): every stage runs
// once on every slice, after the stage before it on the slice and its
// neighbours and before the stage after it on the neighbours; chained
// red–black sweeps give bit for bit what the passes run one after the other
// give, on lattices run serially and cut into chunks of uneven length.
#include "sim/fluid/StencilOperator.h"
#include "sim/fluid/WavefrontSlices.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <random>
#include <vector>

namespace eikon::sim {
namespace {

TEST(WavefrontSlices, EveryStageRunsOnceBetweenItsNeighboursStages) {
    for (int slices : {1, 2, 5, 31, 32, 33, 47, 100, 129}) {
        for (int stages : {1, 2, 3, 5, 8}) {
            SCOPED_TRACE(testing::Message() << slices << " slices, " << stages << " stages");
            const std::size_t count = static_cast<std::size_t>(slices) * stages;
            std::atomic<int> clock{0};
            std::vector<std::atomic<int>> runs(count), start(count), end(count);
            auto at = [&](int q, int k) { return static_cast<std::size_t>(q) * slices + k; };
            const StageTotals totals = runStagesAsWavefront(
                slices, stages, true, 0.0,
                [&](int q, int k) {
                    start[at(q, k)] = clock++;
                    ++runs[at(q, k)];
                    end[at(q, k)] = clock++;
                    return 1.0;
                },
                [](double u, double v) { return u + v; });
            for (int q = 0; q < stages; ++q) {
                EXPECT_EQ(totals[q], slices);
                for (int k = 0; k < slices; ++k) {
                    ASSERT_EQ(runs[at(q, k)], 1) << "stage " << q << ", slice " << k;
                    for (int n = std::max(k - 1, 0); n <= std::min(k + 1, slices - 1); ++n) {
                        if (q > 0) {
                            EXPECT_LT(end[at(q - 1, n)], start[at(q, k)]) << "stage " << q << ", slice " << k;
                        }
                        if (q + 1 < stages && n != k) {
                            EXPECT_LT(end[at(q, k)], start[at(q + 1, n)]) << "stage " << q << ", slice " << k;
                        }
                    }
                }
            }
        }
    }
}

SevenPointOperator operatorWithObstacle(glm::ivec3 size) {
    std::vector<std::uint8_t> active(static_cast<std::size_t>(size.x) * size.y * size.z, 1);
    for (int k = 0; k < size.z; ++k)
        for (int j = 0; j < size.y; ++j)
            for (int i = 0; i < size.x; ++i)
                if ((i - size.x / 2) * (i - size.x / 2) + (j - size.y / 3) * (j - size.y / 3) < 9)
                    active[i + static_cast<std::size_t>(size.x) * (j + static_cast<std::size_t>(size.y) * k)] = 0;
    const bool open[6] = {false, false, false, true, false, false};
    return poissonOperator(size, glm::dvec3(0.1, 0.2, 0.15), active, open);
}

// From x = 0: colours 0, 1, 0, 1, then the residual on colour 0 and b · x.
void expectWavefrontMatchesPasses(glm::ivec3 size) {
    SCOPED_TRACE(testing::Message() << size.x << "x" << size.y << "x" << size.z);
    const SevenPointOperator op = operatorWithObstacle(size);
    std::mt19937 rng(11);
    std::normal_distribution<double> normal;
    std::vector<double> b(op.cellCount());
    for (double& value : b) value = normal(rng);
    const std::vector<double> garbage(op.cellCount(), 3.0);
    auto stage = [&](std::vector<double>& x, std::vector<double>& r, int q, int k) {
        if (q == 0) op.relaxSliceFromZero(b, x, k);
        if (q >= 1 && q <= 3) op.relaxSlice(b, x, k, q % 2);
        if (q == 4) {
            op.residualSliceAfterSweep(b, x, r, k, 0);
            return op.dotSlice(b, x, k);
        }
        return 0.0;
    };
    std::vector<double> expectedX = garbage, expectedR = garbage;
    double expectedDot = 0.0;
    for (int q = 0; q < 5; ++q)
        for (int k = 0; k < size.z; ++k) expectedDot += stage(expectedX, expectedR, q, k);
    std::vector<double> x = garbage, r = garbage;
    const StageTotals totals = runStagesAsWavefront(
        size.z, 5, op.passesInParallel(), 0.0, [&](int q, int k) { return stage(x, r, q, k); }, std::plus<>());
    EXPECT_EQ(x, expectedX);
    EXPECT_EQ(r, expectedR);
    EXPECT_NEAR(totals[4], expectedDot, 1e-12 * static_cast<double>(op.cellCount()));
    double maxResidual = 0.0;
    for (double value : r) maxResidual = std::max(maxResidual, std::abs(value));
    EXPECT_GT(maxResidual, 0.0) << "the sweeps did something to check";
}

// The kernels' branch-free path through the bulk of plain rows gives bit
// for bit what the general path gives there.
TEST(WavefrontSlices, PlainRowsChangeNoResult) {
    const SevenPointOperator op = operatorWithObstacle(glm::ivec3(20, 18, 16));
    SevenPointOperator general = op;
    general.plainRow.clear();
    ASSERT_GT(std::count(op.plainRow.begin(), op.plainRow.end(), 1), 100);
    std::mt19937 rng(5);
    std::normal_distribution<double> normal;
    std::vector<double> b(op.cellCount()), start(op.cellCount());
    for (double& value : b) value = normal(rng);
    for (double& value : start) value = normal(rng);
    std::vector<double> x = start, xGeneral = start, r(op.cellCount()), rGeneral(op.cellCount());
    for (int k = 0; k < op.size.z; ++k) {
        op.relaxSlice(b, x, k, k % 2);
        general.relaxSlice(b, xGeneral, k, k % 2);
        op.residualSliceAfterSweep(b, x, r, k, 1);
        general.residualSliceAfterSweep(b, xGeneral, rGeneral, k, 1);
    }
    EXPECT_EQ(x, xGeneral);
    EXPECT_EQ(r, rGeneral);
    std::vector<double> y(op.cellCount()), yGeneral(op.cellCount());
    EXPECT_NEAR(op.applyAndDot(start, y), general.applyAndDot(start, yGeneral), 1e-9);
    EXPECT_EQ(y, yGeneral);
}

TEST(WavefrontSlices, SerialRedBlackSweepsMatchPassesOneAfterAnother) {
    expectWavefrontMatchesPasses(glm::ivec3(7, 6, 5));
    expectWavefrontMatchesPasses(glm::ivec3(9, 8, 1));
    expectWavefrontMatchesPasses(glm::ivec3(9, 8, 2));
}

TEST(WavefrontSlices, ChunkedRedBlackSweepsMatchPassesOneAfterAnother) {
    expectWavefrontMatchesPasses(glm::ivec3(24, 20, 40));  // two chunks
    expectWavefrontMatchesPasses(glm::ivec3(33, 31, 67));  // uneven chunks
}

}  // namespace
}  // namespace eikon::sim
