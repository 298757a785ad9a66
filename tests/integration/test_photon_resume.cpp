// Photons suspended at the driver's loop cap and resumed by the next
// dispatch (shaders/common/suspended_photons.glsl): a photon must end
// exactly as it would have without the cap, so a small loop budget, which
// suspends each photon many times, gives bit for bit the receiver map and
// every count the driver's own budget gives (on a GPU without a cap, the
// photons are never suspended there), and tracer.max_steps, not the cap,
// is what stops a photon.
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"

#include <gtest/gtest.h>

namespace eikon {
namespace {

using namespace test;

// The inverse-square scene with a sharp glass ball over the receiver, at
// uniform steps of 0.05 voxel: about 500 steps a crossing, with a surface
// search on each, far past llvmpipe's cap of 8191 loops a dispatch.
Scene longPathScene() {
    Scene scene = inverseSquareScene();
    ObjectDesc ball;
    ball.kind = ObjectDesc::Kind::Sphere;
    ball.sphere = {glm::dvec3(0.0, 0.0, 0.0), 0.25};
    ball.material.index = 1.5;
    scene.objects.push_back(ball);
    scene.tracer.stepPolicy = TracerDesc::StepPolicy::Uniform;
    scene.tracer.stepVoxels = 0.05;
    scene.tracer.maxSteps = 1000000;
    scene.render.photons = 4096;
    return scene;
}

TEST(PhotonResume, ASmallLoopBudgetChangesNothingButHowOftenPhotonsAreResumed) {
    const Scene scene = longPathScene();
    const TraceResult driver = trace(scene);
    const TraceResult small = trace(scene, {.loopBudget = 300u});
    test::reportFigure("resumed_photons_at_budget_300", static_cast<double>(small.stats.photonsResumed));
    test::reportFigure("resume_dispatches_at_budget_300", small.stats.resumeDispatches);
    EXPECT_GT(small.stats.photonsResumed, 10u * 4096u) << "each photon suspended many times";
    EXPECT_GT(small.stats.resumeDispatches, 10);
    EXPECT_GT(small.stats.photonsResumed, driver.stats.photonsResumed);

    EXPECT_EQ(small.map, driver.map) << "the receiver map, bit for bit";
    EXPECT_EQ(small.stats.steps, driver.stats.steps);
    EXPECT_EQ(small.stats.photonsReceived, driver.stats.photonsReceived);
    EXPECT_EQ(small.stats.photonsEscaped, driver.stats.photonsEscaped);
    EXPECT_EQ(small.stats.surfaceReflections, driver.stats.surfaceReflections);
    EXPECT_EQ(small.stats.surfaceTransmissions, driver.stats.surfaceTransmissions);
    for (const auto* result : {&driver, &small}) {
        EXPECT_EQ(result->stats.photonsCutOff, 0u) << "max_steps of 10^6 is never reached";
        EXPECT_GT(result->stats.photonsReceived, 500u);
        EXPECT_LT(result->stats.balanceError(), 1e-6);
    }
}

// A budget below one pass of the loop (9 loops here: 4, 2 per receiver, 3
// per sharp surface) cannot move a photon on, and resuming it would loop
// for ever: each is cut off and counted instead, and no round follows.
TEST(PhotonResume, ABudgetBelowOnePassCutsPhotonsOffInsteadOfLoopingForever) {
    const TraceResult result = trace(longPathScene(), {.loopBudget = 8u});
    EXPECT_EQ(result.stats.photonsCutOff, 4096u);
    EXPECT_EQ(result.stats.resumeDispatches, 0);
    EXPECT_LT(result.stats.balanceError(), 1e-6);
}

}  // namespace
}  // namespace eikon
