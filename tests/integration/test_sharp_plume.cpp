// A sharp glass ball inside a graded, moving medium: scenes/plume_lens.json,
// a ball just above a 450 K hot plate whose plume the fluid solver grows
// frame by frame. The ball focuses sunlight onto the plate; the hot air
// bends the light on its way in and out, so the caustic must move as the
// plume grows.
//
// The motion is small (hot air changes n by 1e-4; the ball turns an angle α
// into a shift f·α at its focus, f = 7.5 cm), far below the photon noise of
// the caustic's centroid on the map. So it is measured photon by photon:
// with one seed every photon starts alike in both frames, and the shift of
// each caustic photon's landing point between the still first frame and the
// grown plume is the fields' doing alone. Checked: the mean shift is the
// same for two independent samples of photons (another seed), so it is a
// property of the plume, not of the sample; it points away from the plume's
// axis, toward the cooler and denser air, as the ray equation bends light;
// still air gives no shift at all; energy balances and the maps are finite.
#include "io/scene/SceneParser.h"
#include "render/graph/FrameRenderer.h"
#include "sim/SceneFields.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace eikon {
namespace {

constexpr int kRecorded = 1 << 16, kVertices = 64;

// For each recorded photon that went through the ball and then landed on
// the receiver (the plate's top): where it landed.
std::vector<std::optional<glm::dvec3>> causticLandings(render::FrameRenderer& renderer, const FieldSet& fields) {
    const render::FrameResult result = renderer.render(fields);
    EXPECT_LE(result.photons.balanceError(), 1e-6);
    for (float value : renderer.receivers().download(0)) EXPECT_TRUE(std::isfinite(value));
    const Scene& scene = renderer.scene();
    const glm::dvec3 centre = scene.objects[0].sphere.center;
    const double radius = scene.objects[0].sphere.radius, plate = scene.receivers[0].point.y;
    const std::vector<glm::vec4> paths = renderer.photonStage()->downloadPaths();
    std::vector<std::optional<glm::dvec3>> landings(kRecorded);
    for (int photon = 0; photon < kRecorded; ++photon) {
        bool throughBall = false;
        for (int v = 0; v < kVertices; ++v) {
            const glm::vec4& vertex = paths[static_cast<std::size_t>(photon) * kVertices + v];
            if (vertex.w != 1.0f) break;
            const glm::dvec3 x(vertex);
            throughBall = throughBall || glm::length(x - centre) < 0.99 * radius;
            if (throughBall && std::abs(x.y - plate) < 1e-5) {
                landings[static_cast<std::size_t>(photon)] = x;
                break;
            }
        }
    }
    return landings;
}

struct Shift {
    glm::dvec3 mean{0.0};  // m
    int photons = 0;
};

// The mean shift of the photons that landed in both frames along the same
// history (a shift of 1 mm or more means a Fresnel choice went the other way).
Shift meanShift(const std::vector<std::optional<glm::dvec3>>& before,
                const std::vector<std::optional<glm::dvec3>>& after) {
    Shift shift;
    for (std::size_t p = 0; p < before.size(); ++p) {
        if (!before[p] || !after[p]) continue;
        const glm::dvec3 d = *after[p] - *before[p];
        if (glm::length(d) >= 1e-3) continue;
        shift.mean += d;
        ++shift.photons;
    }
    if (shift.photons > 0) shift.mean /= shift.photons;
    return shift;
}

TEST(SharpPlume, TheCausticOfAGlassBallMovesWithTheHotPlume) {
    test::glContext();
    const std::string path = std::string(EIKON_SOURCE_DIR) + "/scenes/plume_lens.json";
    const Scene scene = loadSceneFile(path, {});
    ASSERT_TRUE(scene.objects[0].isSharp());
    ASSERT_TRUE(scene.sim.has_value());
    const Scene otherSeed = loadSceneFile(path, {"render.seed=2"});
    const int stride = static_cast<int>(scene.render.photons / kRecorded);
    const render::RendererOptions options{
        .photons = {.recordPathVertices = kVertices, .recordedPhotons = kRecorded, .recordStride = stride},
        .tracePhotons = true};
    sim::SceneFields fields(scene);
    render::FrameRenderer first(scene, fields.fields(), options), second(otherSeed, fields.fields(), options);

    const auto stillFirst = causticLandings(first, fields.fields());
    const auto stillSecond = causticLandings(second, fields.fields());
    const Shift none = meanShift(stillFirst, causticLandings(first, fields.fields()));
    EXPECT_EQ(glm::length(none.mean), 0.0) << "the same fields and seed land every photon where it landed";
    constexpr int kFrames = 25;  // 1 s of scene time: the plume has risen past the ball
    for (int frame = 0; frame < kFrames; ++frame) fields.advanceFrame();
    const Shift a = meanShift(stillFirst, causticLandings(first, fields.fields()));
    const Shift b = meanShift(stillSecond, causticLandings(second, fields.fields()));

    test::reportFigure("plume_lens_caustic_photons", a.photons);
    test::reportFigure("plume_lens_caustic_shift_um", glm::length(a.mean) * 1e6);
    test::reportFigure("plume_lens_caustic_shift_other_seed_um", glm::length(b.mean) * 1e6);
    ASSERT_GE(a.photons, 500);
    ASSERT_GE(b.photons, 500);
    EXPECT_GT(glm::length(a.mean), 1e-6) << "m";
    EXPECT_LE(glm::length(a.mean - b.mean), 0.2 * glm::length(a.mean));
    // The ball hangs at the plume's edge (x = 5 cm, the plume's axis at
    // x = 0): light bends toward the cooler, denser air, away from the axis.
    EXPECT_GT(a.mean.x, 0.9 * glm::length(a.mean));
}

}  // namespace
}  // namespace eikon
