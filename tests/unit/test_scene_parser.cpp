// Scene files: every section parsed (bad values: test_scene_parser_errors.cpp).
#include "io/scene/SceneParser.h"

#include "tests/unit/SceneParserTestSupport.h"

#include <gtest/gtest.h>

#include <string>

namespace eikon {
namespace {

using namespace test;

TEST(SceneParser, ParsesAFullScene) {
    const Scene scene = parseScene(validScene(), "test.json");
    EXPECT_EQ(scene.sourcePath, "test.json");

    EXPECT_EQ(scene.grid.resolution, glm::ivec3(32, 16, 8));
    EXPECT_EQ(scene.grid.boundsMin, glm::dvec3(-1, -0.5, -2));
    EXPECT_EQ(scene.grid.boundsMax, glm::dvec3(1, 0.5, 2));
    EXPECT_DOUBLE_EQ(scene.grid.smoothingSigmaVoxels, 0.75);
    EXPECT_EQ(scene.grid.supersampling, 2);

    EXPECT_DOUBLE_EQ(scene.medium.index, 1.0003);
    EXPECT_EQ(scene.medium.extinction, Rgb(0.01));  // grey value expanded to all channels
    EXPECT_EQ(scene.medium.scattering, Rgb(0.001, 0.002, 0.003));

    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_EQ(scene.objects[0].kind, ObjectDesc::Kind::Sphere);
    EXPECT_EQ(scene.objects[0].sphere.center, glm::dvec3(0, 0.1, 0));
    EXPECT_DOUBLE_EQ(scene.objects[0].sphere.radius, 0.4);
    EXPECT_DOUBLE_EQ(scene.objects[0].material.index, 1.5);
    EXPECT_EQ(scene.objects[0].material.scattering, Rgb(0.0));  // default
    EXPECT_EQ(scene.objects[1].kind, ObjectDesc::Kind::Box);
    EXPECT_EQ(scene.objects[1].box.max, glm::dvec3(0.5, 0, 0.5));
    EXPECT_EQ(scene.objects[1].material.extinction, Rgb(2.0));

    ASSERT_EQ(scene.lights.size(), 2u);
    EXPECT_EQ(scene.lights[0].kind, LightDesc::Kind::Point);
    EXPECT_EQ(scene.lights[0].power, Rgb(10, 20, 30));
    EXPECT_EQ(scene.lights[1].kind, LightDesc::Kind::Directional);
    EXPECT_EQ(scene.lights[1].direction, glm::dvec3(0, -1, 0));  // normalised
    EXPECT_EQ(scene.lights[1].irradiance, Rgb(500.0));

    ASSERT_EQ(scene.receivers.size(), 2u);
    EXPECT_EQ(scene.receivers[0].normal, glm::dvec3(0, 1, 0));  // normalised
    EXPECT_EQ(scene.receivers[0].albedo, Rgb(0.8));              // defaults
    EXPECT_DOUBLE_EQ(scene.receivers[0].size, 2.0);
    EXPECT_EQ(scene.receivers[0].resolution, 256);
    EXPECT_EQ(scene.receivers[1].albedo, Rgb(0.2, 0.5, 1.0));
    EXPECT_EQ(scene.receivers[1].resolution, 512);

    EXPECT_EQ(scene.camera.position, glm::dvec3(0, 1, 4));
    EXPECT_DOUBLE_EQ(scene.camera.fovDeg, 35.0);

    EXPECT_EQ(scene.render.photons, 1000000);
    EXPECT_EQ(scene.render.width, 320);
    EXPECT_EQ(scene.render.height, 240);
    EXPECT_EQ(scene.render.seed, 7u);
    EXPECT_DOUBLE_EQ(scene.render.exposureEv, -1.5);
    EXPECT_DOUBLE_EQ(scene.render.stepVoxels, 0.25);
    EXPECT_EQ(scene.render.environment.radiance, Rgb(0.1));
}

TEST(SceneParser, ParsesNewKeys) {
    const Scene scene = parseScene(sceneWithNewKeys(), "test.json");
    EXPECT_EQ(scene.grid.smoothingWindowVoxels, 5);

    ASSERT_EQ(scene.lights.size(), 3u);
    const LightDesc& spot = scene.lights[2];
    EXPECT_EQ(spot.kind, LightDesc::Kind::Spot);
    EXPECT_EQ(spot.position, glm::dvec3(1, 2, 3));
    EXPECT_EQ(spot.direction, glm::dvec3(0, 0, -1));  // normalised
    EXPECT_EQ(spot.power, Rgb(1, 2, 3));
    EXPECT_DOUBLE_EQ(spot.coneAngleDeg, 45.0);
    EXPECT_DOUBLE_EQ(spot.falloffDeg, 10.0);

    const TracerDesc& tracer = scene.tracer;
    EXPECT_EQ(tracer.integrator, TracerDesc::Integrator::Rk4);
    EXPECT_EQ(tracer.stepPolicy, TracerDesc::StepPolicy::Uniform);
    EXPECT_DOUBLE_EQ(tracer.stepVoxels, 0.25);
    EXPECT_DOUBLE_EQ(tracer.maxStepVoxels, 4.0);
    EXPECT_DOUBLE_EQ(tracer.epsilon, 0.001);
    EXPECT_DOUBLE_EQ(tracer.epsilonPrime, 0.01);
    EXPECT_TRUE(tracer.renormalize);
    EXPECT_DOUBLE_EQ(tracer.powerCutoff, 0.5);
    EXPECT_EQ(tracer.maxSteps, 100000);
    EXPECT_EQ(tracer.dispersion, Rgb(0.9, 1.0, 1.1));
    EXPECT_TRUE(tracer.storeFluence);

    EXPECT_DOUBLE_EQ(scene.render.stepVoxels, 0.25);  // the camera step stays separate
}

TEST(SceneParser, IntegratorAndStepPolicyNames) {
    json scene = validScene();
    scene["tracer"] = {{"integrator", "euler"}, {"step_policy", "octree"}};
    EXPECT_EQ(parseScene(scene, "test.json").tracer.integrator, TracerDesc::Integrator::Euler);
    EXPECT_EQ(parseScene(scene, "test.json").tracer.stepPolicy, TracerDesc::StepPolicy::Octree);
    scene["tracer"]["integrator"] = "leapfrog";
    EXPECT_EQ(parseScene(scene, "test.json").tracer.integrator, TracerDesc::Integrator::Leapfrog);
}

TEST(SceneParser, NewKeysTakeDefaults) {
    json scene = validScene();
    scene["lights"].push_back(json::parse(R"({"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0],
        "power": 2})"));
    scene["tracer"] = json::object();
    const Scene parsed = parseScene(scene, "test.json");
    const Scene defaults;
    EXPECT_EQ(parsed.grid.smoothingWindowVoxels, 0);  // automatic
    EXPECT_DOUBLE_EQ(parsed.lights[2].coneAngleDeg, 30.0);
    EXPECT_DOUBLE_EQ(parsed.lights[2].falloffDeg, 5.0);

    for (const TracerDesc& tracer : {parsed.tracer, parseScene(validScene(), "test.json").tracer}) {
        EXPECT_EQ(tracer.integrator, TracerDesc::Integrator::Leapfrog);
        EXPECT_EQ(tracer.stepPolicy, TracerDesc::StepPolicy::Octree);
        EXPECT_DOUBLE_EQ(tracer.stepVoxels, 0.5);
        EXPECT_DOUBLE_EQ(tracer.maxStepVoxels, 8.0);
        EXPECT_DOUBLE_EQ(tracer.epsilon, 0.002);
        EXPECT_DOUBLE_EQ(tracer.epsilonPrime, 0.002);
        EXPECT_FALSE(tracer.renormalize);
        EXPECT_DOUBLE_EQ(tracer.powerCutoff, 1e-4);
        EXPECT_EQ(tracer.maxSteps, 0);
        EXPECT_EQ(tracer.dispersion, Rgb(1.0));
        EXPECT_FALSE(tracer.storeFluence);
        EXPECT_EQ(tracer.maxStepVoxels, defaults.tracer.maxStepVoxels);
        EXPECT_EQ(tracer.multipleScattering, TracerDesc::MultipleScattering::None);
        EXPECT_EQ(tracer.lattice.directions, 14);
        EXPECT_DOUBLE_EQ(tracer.lattice.tolerance, 1e-3);
        EXPECT_EQ(tracer.lattice.maxIterations, 4000);
    }
}

// render.device: where the grid passes run (render/stages/StageDevice.h).
TEST(SceneParser, RenderDeviceNamesWhereTheGridPassesRun) {
    json scene = validScene();
    EXPECT_EQ(parseScene(scene, "test.json").render.device, ComputeDevice::Auto);
    scene["render"]["device"] = "cpu";
    EXPECT_EQ(parseScene(scene, "test.json").render.device, ComputeDevice::Cpu);
    scene["render"]["device"] = "gpu";
    EXPECT_EQ(parseScene(scene, "test.json").render.device, ComputeDevice::Gpu);
}

TEST(SceneParser, MultipleScatteringKeys) {
    json scene = validScene();
    scene["tracer"] = json::parse(R"({"multiple_scattering": "lbm", "lbm_directions": 14, "lbm_tolerance": 1e-5,
                                      "lbm_max_iterations": 250})");
    const TracerDesc tracer = parseScene(scene, "test.json").tracer;
    EXPECT_EQ(tracer.multipleScattering, TracerDesc::MultipleScattering::Lbm);
    EXPECT_EQ(tracer.lattice.directions, 14);
    EXPECT_DOUBLE_EQ(tracer.lattice.tolerance, 1e-5);
    EXPECT_EQ(tracer.lattice.maxIterations, 250);
}

// An absent bound follows the value it must not fall below, rather than
// rejecting a key the file does not contain.
TEST(SceneParser, DefaultBoundsFollowTheirLimits) {
    json scene = validScene();
    scene["tracer"] = {{"step_voxels", 12}, {"epsilon", 0.05}};
    scene["lights"][0] = json::parse(R"({"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0],
        "power": 2, "cone_angle_deg": 3})");
    const Scene parsed = parseScene(scene, "test.json");
    EXPECT_DOUBLE_EQ(parsed.tracer.maxStepVoxels, 12.0);
    EXPECT_DOUBLE_EQ(parsed.tracer.epsilonPrime, 0.05);
    EXPECT_DOUBLE_EQ(parsed.lights[0].falloffDeg, 3.0);
}

TEST(SceneParser, BoundaryValuesAreAccepted) {
    json scene = sceneWithNewKeys();
    scene["grid"]["smoothing_window_voxels"] = 1;
    scene["lights"][2]["falloff_deg"] = 45;  // equal to the cone angle
    scene["tracer"]["max_step_voxels"] = 0.25;  // equal to step_voxels
    scene["tracer"]["epsilon_prime"] = 0.001;   // equal to epsilon
    scene["tracer"]["power_cutoff"] = 0;
    scene["tracer"]["max_steps"] = 2147483647LL;
    EXPECT_NO_THROW(parseScene(scene, "test.json"));
    scene["grid"]["smoothing_window_voxels"] = 63;
    scene["lights"][2]["falloff_deg"] = 0;
    EXPECT_NO_THROW(parseScene(scene, "test.json"));
}

TEST(SceneParser, MinimalSceneTakesDefaults) {
    const Scene scene = parseScene(json::parse(R"({"lights": [{"type": "point", "position": [0, 1, 0], "power": 1}]})"),
                                   "test.json");
    const Scene defaults;
    EXPECT_EQ(scene.grid.resolution, defaults.grid.resolution);
    EXPECT_DOUBLE_EQ(scene.medium.index, 1.0);
    EXPECT_TRUE(scene.objects.empty());
    EXPECT_TRUE(scene.receivers.empty());
    EXPECT_EQ(scene.camera.position, defaults.camera.position);
    EXPECT_EQ(scene.render.photons, defaults.render.photons);
}

TEST(SceneParser, ReceiverBounceIsReadAndDefaultsToStopping) {
    json scene = validScene();
    EXPECT_FALSE(parseScene(scene, "test.json").receivers[0].bounce);
    scene["receivers"][0]["bounce"] = true;
    EXPECT_TRUE(parseScene(scene, "test.json").receivers[0].bounce);
}

// A square up to 1024 rays per pixel (the others: test_scene_parser_errors.cpp).
TEST(SceneParser, SamplesPerPixelOfASquareIsRead) {
    json scene = validScene();
    scene["render"]["samples_per_pixel"] = 9;
    EXPECT_EQ(parseScene(scene, "scene.json").render.samplesPerPixel, 9);
}

// Input quoted in a message is cut to a line: a 4 MB unknown key or string
// value gives a short message that still names where.
TEST(SceneParser, LongKeysAndValuesAreClippedInMessages) {
    json root = validScene();
    root[std::string(4 << 20, 'k')] = 1;
    const std::string key = parseErrorMessage(root);
    EXPECT_LT(key.size(), 600u) << key.substr(0, 200);
    EXPECT_NE(key.find("characters)"), std::string::npos) << key.substr(0, 200);
    json value = validScene();
    value["objects"][0]["type"] = std::string(4 << 20, 'v');
    const std::string found = parseErrorMessage(value);
    EXPECT_LT(found.size(), 600u);
    EXPECT_NE(found.find("objects[0].type"), std::string::npos) << found;
}

}  // namespace
}  // namespace eikon
