// The viewer's preview policy (apps/viewer/ViewPreview): the full image
// at rest, a stride that keeps the view pass to its target while the camera
// moves, the full image again once the camera has rested.
#include "apps/viewer/ViewPreview.h"

#include <gtest/gtest.h>

namespace eikon::view {
namespace {

PreviewSettings settings() {
    PreviewSettings s;
    s.targetViewMs = 40.0;
    s.refineDelaySeconds = 0.25;
    s.largestStride = 8;
    return s;
}

TEST(ViewPreview, FullImageUntilTheCameraMoves) {
    ViewPreview preview(settings());
    EXPECT_EQ(preview.strideFor(false, 0.0), 1);
    preview.measured(1, 400.0);
    EXPECT_EQ(preview.strideFor(false, 0.1), 1);
}

TEST(ViewPreview, StrideKeepsTheViewPassToItsTarget) {
    ViewPreview preview(settings());
    preview.measured(1, 400.0);  // full image: 400 ms, ten times the target
    // k² ≥ 10: a 4×4 stride traces 1/16 of the rays, 25 ms.
    EXPECT_EQ(preview.strideFor(true, 1.0), 4);
    // A preview frame's time sets the next: 4×4 at 40 ms means 640 ms full, so 4.
    preview.measured(4, 40.0);
    EXPECT_EQ(preview.strideFor(true, 1.05), 4);
    preview.measured(4, 60.0);  // 960 ms full: 5×5
    EXPECT_EQ(preview.strideFor(true, 1.1), 5);
}

// A full image of k² rays a pixel costs k² one-ray images; a preview traces
// one ray a block: the stride is set by the cost of one ray.
TEST(ViewPreview, StrideIsSetByTheCostOfOneRay) {
    ViewPreview preview(settings());
    preview.measured(1, 400.0, 4);  // 4 rays a pixel in 400 ms: one ray a pixel 100 ms
    // k² ≥ 2.5: a 2×2 stride, 25 ms (not the 4×4 that 400 ms of one ray a pixel would want).
    EXPECT_EQ(preview.strideFor(true, 1.0), 2);
    preview.measured(2, 25.0);
    EXPECT_EQ(preview.strideFor(true, 1.05), 2);

    ViewPreview cheapRays(settings());
    cheapRays.measured(1, 80.0, 4);  // twice the target, though one ray a pixel (20 ms) is within it
    EXPECT_EQ(cheapRays.strideFor(true, 1.0), 2) << "a preview is one ray a block, at least 2×2";
    cheapRays.measured(1, 36.0, 4);  // the full image within the target: no preview
    EXPECT_EQ(cheapRays.strideFor(true, 1.1), 1);
}

TEST(ViewPreview, ImageSpacePreviewShrinksToKeepItsViewPassToTheTarget) {
    ViewPreview preview(settings());
    EXPECT_EQ(preview.imageSpaceScale(), 1) << "full size until measured";
    preview.measuredImageSpace(1, 30.0);
    EXPECT_EQ(preview.imageSpaceScale(), 1) << "within the target";
    preview.measuredImageSpace(1, 100.0);  // 2.5 times the target: half size draws a quarter of the pixels
    EXPECT_EQ(preview.imageSpaceScale(), 2);
    preview.measuredImageSpace(2, 20.0);  // 80 ms at full size
    EXPECT_EQ(preview.imageSpaceScale(), 2);
    preview.measuredImageSpace(2, 500.0);  // 2 s at full size: capped
    EXPECT_EQ(preview.imageSpaceScale(), 4);
    EXPECT_EQ(preview.strideFor(false, 0.0), 1) << "the eikonal stride is measured apart";
}

TEST(ViewPreview, RefinesOnceTheCameraHasRested) {
    ViewPreview preview(settings());
    preview.measured(1, 400.0);
    EXPECT_EQ(preview.strideFor(true, 1.0), 4);
    EXPECT_EQ(preview.strideFor(false, 1.2), 4);  // still within the refine delay
    EXPECT_EQ(preview.strideFor(false, 1.25), 1);
    EXPECT_EQ(preview.strideFor(true, 2.0), 4);  // moving again
}

TEST(ViewPreview, AFastViewNeedsNoPreviewAndStridesAreCapped) {
    ViewPreview fast(settings());
    fast.measured(1, 30.0);  // already within the target (a GPU)
    EXPECT_EQ(fast.strideFor(true, 1.0), 1);

    ViewPreview slow(settings());
    slow.measured(1, 40.0 * 200.0);  // would want 15×15
    EXPECT_EQ(slow.strideFor(true, 1.0), 8);

    ViewPreview unmeasured(settings());
    EXPECT_EQ(unmeasured.strideFor(true, 1.0), 1);  // no cost known yet: the full image
}

TEST(ViewPreview, AFrameWhoseViewDidNotRunKeepsTheEstimate) {
    ViewPreview preview(settings());
    preview.measured(1, 400.0);
    preview.measured(1, 0.0);  // the view pass did not run (nothing changed)
    EXPECT_EQ(preview.strideFor(true, 1.0), 4);
}

TEST(ViewPreview, TheCameraCountsAsMovingUntilTheRefineDelayHasPassed) {
    ViewPreview preview(settings());
    EXPECT_FALSE(preview.cameraMoving(0.0)) << "not before it first moves";
    preview.measured(1, 10.0);  // a view within the target: no stride, yet the camera moves
    EXPECT_EQ(preview.strideFor(true, 1.0), 1);
    EXPECT_TRUE(preview.cameraMoving(1.0));
    EXPECT_EQ(preview.strideFor(false, 1.2), 1);
    EXPECT_TRUE(preview.cameraMoving(1.2));
    EXPECT_EQ(preview.strideFor(false, 1.25), 1);
    EXPECT_FALSE(preview.cameraMoving(1.25));
}

}  // namespace
}  // namespace eikon::view
