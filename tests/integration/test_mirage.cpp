// The inferior mirage of scenes/hot_road_mirage.json against its closed
// form. In still air layered in height, n(y)·cos θ(y) is constant along a
// ray (Snell's law in a stratified medium; θ the angle to the horizontal): a
// ray that enters the hot layer at depression α from air of index n_top
// turns back up where n(y) = n_top·cos α — above the road if and only if
// α < α_c = arccos(n(0) / n_top) ≈ √(2·(n_top − n(0))) — and leaves the layer
// at elevation α, symmetric to how it came. So from the horizon down to α_c
// below it the road shows the sky at the mirrored elevation, upside down;
// steeper rays meet the road. The index is Gladstone–Dale's,
// n − 1 = (n0 − 1)·T0/T(y), over the scene's T(y) = T_air + ΔT·exp(−y/H),
// computed here from the scene's keys, not from the renderer's fields.
#include "io/scene/SceneParser.h"
#include "render/graph/FrameRenderer.h"
#include "sim/SceneFields.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>

namespace eikon {
namespace {

TEST(Mirage, TheRoadShowsTheSkyMirroredDownToTheCriticalAngle) {
    test::glContext();
    Scene scene = loadSceneFile(std::string(EIKON_SOURCE_DIR) + "/scenes/hot_road_mirage.json",
                                {"render.width=8", "render.height=240"});
    scene.receivers.clear();  // the truck and the tree: the columns here see the open road
    const sim::SceneFields sceneFields(scene);
    render::FrameRenderer renderer(scene, sceneFields.fields(), {.photons = {}, .recordViewExits = true});
    renderer.render(sceneFields.fields());
    const std::vector<glm::vec4> exits = renderer.viewStage().downloadExits();

    // n0 − 1 = 2.93e-4 at T0 = 273.15 K (sim/optics/AirOptics.h's reference state).
    const double ground = 330.0, air = 300.0, height = 0.1, gridTop = 1.0;
    const auto index = [&](double y) { return 1.0 + 2.93e-4 * 273.15 / (air + (ground - air) * std::exp(-y / height)); };
    const double critical = std::acos(index(0.0) / index(gridTop));
    test::reportFigure("mirage_critical_angle_mrad", critical * 1e3);

    const glm::dvec3 forward = glm::normalize(scene.camera.target - scene.camera.position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, scene.camera.up));
    const glm::dvec3 up = glm::cross(right, forward);
    const double tanHalf = std::tan(scene.camera.fovDeg * M_PI / 360.0);
    const int column = scene.render.width / 2;
    double lowestMirrored = 0.0, highestOnRoad = 1.0, worstMirror = 0.0;
    int mirrored = 0, onRoad = 0;
    for (int row = 0; row < scene.render.height; ++row) {
        const double ndcY = (row + 0.5) / scene.render.height * 2.0 - 1.0;
        const double ndcX = (column + 0.5) / scene.render.width * 2.0 - 1.0;
        const glm::dvec3 d = glm::normalize(forward + ndcX * tanHalf * scene.render.width / scene.render.height * right -
                                            ndcY * tanHalf * up);
        const double depression = -std::asin(d.y);
        const glm::vec4 exit = exits[static_cast<std::size_t>(row * scene.render.width + column)];
        ASSERT_EQ(exit.w, 1.0f) << "row " << row << " leaves to the environment";
        const double elevation = std::asin(static_cast<double>(exit.y));
        // Rays shallower than 2 mrad turn more than 1 km away and may reach
        // the grid's far end, 3 km off, before they are out of the layer.
        if (depression < 2e-3) continue;
        if (elevation > 0.0) {
            ++mirrored;
            lowestMirrored = std::max(lowestMirrored, depression);
            worstMirror = std::max(worstMirror, std::abs(elevation - depression) / depression);
        } else {
            ++onRoad;
            highestOnRoad = std::min(highestOnRoad, depression);
        }
    }
    test::reportFigure("mirage_lowest_mirrored_mrad", lowestMirrored * 1e3);
    test::reportFigure("mirage_highest_road_mrad", highestOnRoad * 1e3);
    test::reportFigure("mirage_worst_mirror_error", worstMirror);
    EXPECT_GT(mirrored, 20);
    EXPECT_GT(onRoad, 20);
    // The boundary lies between two rows (0.12 mrad apart) that bracket α_c,
    // to the leapfrog's error over steps that cross one 2 cm layer of the
    // 0.1 m hot layer each (render.step_voxels, on the grid's flat voxels):
    // within 2% of α_c.
    EXPECT_LT(lowestMirrored, highestOnRoad);
    EXPECT_NEAR(lowestMirrored, critical, 0.02 * critical);
    EXPECT_NEAR(highestOnRoad, critical, 0.02 * critical);
    // A turned ray leaves at the elevation it came down at: the mirror.
    EXPECT_LT(worstMirror, 0.01);
}

}  // namespace
}  // namespace eikon
