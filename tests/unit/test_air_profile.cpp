// The air temperature profile of a mirage scene: Gladstone–Dale at the ground
// and far above it, the scene keys, and its conflict with a simulated medium.
#include "io/scene/SceneParser.h"
#include "sim/voxelize/AnalyticVoxelizer.h"
#include "tests/unit/SceneParserTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>

namespace eikon {
namespace {

using test::json;

// n − 1 = 2.93e-4 · (p/p0) · (273.15 K / T) with p = p0 (sim/optics/AirOptics.h).
double airIndex(double kelvin) { return 1.0 + 2.93e-4 * 273.15 / kelvin; }

TEST(AirProfile, FollowsGladstoneDaleFromGroundToAir) {
    AirTemperatureProfile profile;
    profile.groundHeight = 0.2;
    profile.groundTemperature = 330.0;
    profile.airTemperature = 300.0;
    profile.scaleHeight = 0.1;
    EXPECT_NEAR(sim::airProfileIndex(profile, 0.2), airIndex(330.0), 1e-12);
    EXPECT_NEAR(sim::airProfileIndex(profile, 0.0), airIndex(330.0), 1e-12);  // below the ground: ground air
    EXPECT_NEAR(sim::airProfileIndex(profile, 5.0), airIndex(300.0), 1e-12);
    const double oneScaleUp = 300.0 + 30.0 * std::exp(-1.0);
    EXPECT_NEAR(sim::airProfileIndex(profile, 0.3), airIndex(oneScaleUp), 1e-12);
}

TEST(AirProfile, VoxelizedIntoDeltaIndexByHeight) {
    json root = test::validScene();
    root["medium"] = json::parse(R"({"index": 1.000266, "air_temperature_profile":
        {"ground_temperature": 330, "air_temperature": 300, "scale_height": 0.1}})");
    root["objects"] = json::array();
    const Scene scene = parseScene(root, "scene.json");
    ASSERT_TRUE(scene.airProfile);
    const FieldSet fields = sim::voxelizeScene(scene);
    const glm::ivec3 r = fields.grid.resolution;
    for (int j = 0; j < r.y; j += 3) {
        const double y = fields.grid.cellCentre(0, j, 0).y;
        const double expected = sim::airProfileIndex(*scene.airProfile, y) - 1.000266;
        EXPECT_NEAR(fields.deltaIndex[fields.grid.linearIndex(r.x - 1, j, r.z - 1)], expected, 1e-10) << j;
    }
}

TEST(AirProfile, BadKeysAndASimulatedMediumAreRefused) {
    json root = test::validScene();
    root["medium"]["air_temperature_profile"] = json::parse(R"({"ground_temperature": 330, "air_temperature": 300})");
    test::expectErrorAt(root, "medium.air_temperature_profile.scale_height");
    root["medium"]["air_temperature_profile"]["scale_height"] = -1;
    test::expectErrorAt(root, "medium.air_temperature_profile.scale_height", "> 0");
    root["medium"]["air_temperature_profile"]["scale_height"] = 0.1;
    root["sim"] = json::parse(R"({"fluid": "air", "resolution": [8, 8, 8]})");
    test::expectErrorAt(root, "medium.air_temperature_profile", "sim section");
}

}  // namespace
}  // namespace eikon
