// The converge study's rungs (verify/converge/ConvergeLadder): refining the
// wavefront refines every threshold it splits on, the reflected branches'
// reflection_split among them (within the 0 to 1 the scene file holds), and
// leaves that split off where the scene turned it off.
#include "verify/converge/ConvergeLadder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace eikon {
namespace {

Scene wavefrontScene(double reflectionSplit) {
    Scene scene;
    scene.tracer.estimator = TracerDesc::Estimator::Wavefront;
    scene.tracer.wavefront.reflectionSplit = reflectionSplit;
    return scene;
}

bool overrides(const converge::Rung& rung, const std::string& assignment) {
    return std::find(rung.overrides.begin(), rung.overrides.end(), assignment) != rung.overrides.end();
}

TEST(ConvergeLadder, TheWavefrontsReflectionSplitRefinesWithItsThresholds) {
    converge::Refinement four;
    four.photons = 4.0;
    const converge::Rung rung = converge::refinedRung(wavefrontScene(1e-3), "refinement", four);
    EXPECT_DOUBLE_EQ(rung.scene.tracer.wavefront.reflectionSplit, 2.5e-4);
    EXPECT_TRUE(overrides(rung, "tracer.wavefront.reflection_split=0.00025")) << rung.setting;
    EXPECT_NE(rung.setting.find("reflection_split=0.00025"), std::string::npos) << rung.setting;

    converge::Refinement eighth;
    eighth.photons = 0.125;
    EXPECT_DOUBLE_EQ(converge::refinedRung(wavefrontScene(1e-3), "refinement", eighth).scene.tracer.wavefront.reflectionSplit,
                     8e-3);
}

// Coarser rungs coarsen it no further than the scene file holds (1: off).
TEST(ConvergeLadder, ACoarserReflectionSplitStopsAtOne) {
    converge::Refinement eighth;
    eighth.photons = 0.125;
    const converge::Rung rung = converge::refinedRung(wavefrontScene(0.5), "refinement", eighth);
    EXPECT_EQ(rung.scene.tracer.wavefront.reflectionSplit, 1.0);
}

TEST(ConvergeLadder, AReflectionSplitTurnedOffStaysOff) {
    converge::Refinement four;
    four.photons = 4.0;
    const converge::Rung rung = converge::refinedRung(wavefrontScene(1.0), "refinement", four);
    EXPECT_EQ(rung.scene.tracer.wavefront.reflectionSplit, 1.0);
    EXPECT_TRUE(overrides(rung, "tracer.wavefront.reflection_split=1")) << rung.setting;
}

}  // namespace
}  // namespace eikon
