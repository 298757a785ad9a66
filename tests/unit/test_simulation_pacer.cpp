// The viewer's pacing of a moving scene while the camera moves
// (apps/eikon-view/SimulationPacer): every frame advances at rest; while the
// camera moves, frames that only redraw the camera pay for the slower pair
// of frames that simulate and then draw the new fields, so that the mean
// keeps to the target.
#include "apps/eikon-view/SimulationPacer.h"

#include <gtest/gtest.h>

#include <vector>

namespace eikon::view {
namespace {

constexpr double kTarget = 1000.0 / 15.0;

struct FrameCosts {
    double simulateMs;  // a frame that advances the scene
    double drawMs;      // the next, which draws the new fields
    double redrawMs;    // any other: the camera alone
};

// Runs `frames` frames while the camera moves; returns which advanced.
std::vector<bool> orbit(SimulationPacer& pacer, int frames, FrameCosts costs) {
    std::vector<bool> advanced;
    for (int i = 0; i < frames; ++i) {
        const bool advance = pacer.advances(true);
        const bool drawsNewFields = !advanced.empty() && advanced.back();
        pacer.frameDone(advance, true, advance ? costs.simulateMs : drawsNewFields ? costs.drawMs : costs.redrawMs);
        advanced.push_back(advance);
    }
    return advanced;
}

double meanFrameMs(const std::vector<bool>& advanced, FrameCosts costs) {
    double total = 0.0;
    for (std::size_t i = 0; i < advanced.size(); ++i)
        total += advanced[i] ? costs.simulateMs : (i > 0 && advanced[i - 1]) ? costs.drawMs : costs.redrawMs;
    return total / static_cast<double>(advanced.size());
}

TEST(SimulationPacer, AdvancesEveryFrameAtRest) {
    SimulationPacer pacer(kTarget);
    for (int i = 0; i < 5; ++i) {
        EXPECT_TRUE(pacer.advances(false));
        pacer.frameDone(true, false, 300.0);
    }
}

TEST(SimulationPacer, NeverAdvancesOnTheFrameThatDrawsTheLastAdvance) {
    SimulationPacer pacer(kTarget);
    // A cheap scene advances as often as its fields can be drawn: every other frame.
    const std::vector<bool> advanced = orbit(pacer, 6, {10.0, 40.0, 20.0});
    EXPECT_EQ(advanced, (std::vector<bool>{true, false, true, false, true, false}));
}

TEST(SimulationPacer, RedrawsPayForTheSlowerAdvances) {
    SimulationPacer pacer(kTarget);
    // 60 ms to simulate and 120 ms to draw the new fields: with one redraw of
    // 40 ms the three frames average 73 ms, above 66.7; with two, 65 ms.
    const FrameCosts costs{60.0, 120.0, 40.0};
    const std::vector<bool> advanced = orbit(pacer, 9, costs);
    EXPECT_EQ(advanced, (std::vector<bool>{true, false, false, false, true, false, false, false, true}));
    EXPECT_LE(meanFrameMs(std::vector<bool>(advanced.begin(), advanced.begin() + 8), costs), kTarget);
}

TEST(SimulationPacer, TheFirstAdvanceWhileMovingIsMeasuredNotGuessed) {
    SimulationPacer pacer(kTarget);
    pacer.frameDone(true, false, 900.0);  // at rest: says nothing of a frame while the camera moves
    EXPECT_FALSE(pacer.advances(true)) << "this frame draws the fields of the last";
    pacer.frameDone(false, true, 800.0);
    EXPECT_TRUE(pacer.advances(true));
}

TEST(SimulationPacer, NeverHoldsTheSimulationLongerThanItsLimit) {
    SimulationPacer pacer(kTarget);
    // Redraws alone miss the target: the scene still advances each time
    // kLongestHoldMs of redraws has passed.
    const std::vector<bool> advanced = orbit(pacer, 16, {100.0, 300.0, 100.0});
    int advances = 0;
    for (bool a : advanced) advances += a ? 1 : 0;
    EXPECT_FALSE(advanced[6]);
    EXPECT_TRUE(advanced[7]) << "after the drawing frame and five redraws of 100 ms";
    EXPECT_EQ(advances, 3);
}

TEST(SimulationPacer, NoTargetNeverHolds) {
    SimulationPacer pacer(0.0);
    for (bool advanced : orbit(pacer, 6, {500.0, 500.0, 10.0})) EXPECT_TRUE(advanced);
}

}  // namespace
}  // namespace eikon::view
