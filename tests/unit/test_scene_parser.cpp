// Scene files: every section parsed, and bad values reported at their JSON path.
#include "io/scene/SceneParser.h"

#include "bridge/core/Error.h"
#include "tests/unit/SceneParserTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <string>
#include <tuple>

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

// validScene() with every key added since the first format: a spot light as
// lights[2], a smoothing window and a full tracer section.
json sceneWithNewKeys() {
    json scene = validScene();
    scene["grid"]["smoothing_window_voxels"] = 5;
    scene["lights"].push_back(json::parse(R"({"type": "spot", "position": [1, 2, 3], "direction": [0, 0, -2],
        "power": [1, 2, 3], "cone_angle_deg": 45, "falloff_deg": 10})"));
    scene["tracer"] = json::parse(R"({"integrator": "rk4", "step_policy": "uniform", "step_voxels": 0.25,
        "max_step_voxels": 4, "epsilon": 0.001, "epsilon_prime": 0.01, "renormalize": true, "power_cutoff": 0.5,
        "max_steps": 100000, "dispersion": [0.9, 1, 1.1], "store_fluence": true})");
    return scene;
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
    scene["render"]["device"] = "native";
    expectErrorAt(scene, "render.device", "one of");
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

TEST(SceneParserErrors, MultipleScatteringValuesAreRefusedAtTheirPath) {
    for (const auto& [key, value, detail] :
         {std::tuple<const char*, json, const char*>{"multiple_scattering", "diffusion", "\"lbm\""},
          {"lbm_directions", 12, "6, 14 or 18"},
          {"lbm_directions", 26, "18"},
          {"lbm_tolerance", 0, "(0, 1)"},
          {"lbm_tolerance", 1, "(0, 1)"},
          {"lbm_max_iterations", 0, ""}}) {
        json scene = validScene();
        scene["tracer"] = {{key, value}};
        expectErrorAt(scene, std::string("tracer.") + key, detail);
    }
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

TEST(SceneParserErrors, UnknownTopLevelKey) {
    json scene = validScene();
    scene["lightz"] = json::array();
    expectErrorAt(scene, "lightz", "\"lights\"");  // lists the allowed keys
}

// Values the documented ranges used to admit and later stages could not
// hold: g that float32 rounds to 1, powers whose tallies overflow to
// infinity (null in the report), grid corners whose extent does.
TEST(SceneParserErrors, ValuesBeyondWhatTheFieldsAndTalliesHoldAreRefusedAtTheirPath) {
    json scene = validScene();
    scene["medium"]["anisotropy"] = 0.9999999999;
    expectErrorAt(scene, "medium.anisotropy", "0.99999");
    scene = validScene();
    scene["lights"][0]["power"] = 1e308;
    expectErrorAt(scene, "lights[0].power", "1e+30");
    scene = validScene();
    scene["grid"]["bounds"]["max"][0] = 1e308;
    expectErrorAt(scene, "grid.bounds.max[0]", "1000000000]");
}

TEST(SceneParserErrors, UnknownNestedKey) {
    json scene = validScene();
    scene["objects"][0].erase("radius");
    scene["objects"][0]["radus"] = 0.4;
    expectErrorAt(scene, "objects[0].radus", "found an unknown key");
}

TEST(SceneParserErrors, KeyOfAnotherObjectType) {
    json scene = validScene();
    scene["objects"][1]["radius"] = 0.4;  // objects[1] is a box
    expectErrorAt(scene, "objects[1].radius", "\"min\", \"max\"");
}

TEST(SceneParserErrors, StringForANumber) {
    json scene = validScene();
    scene["objects"][0]["radius"] = "big";
    expectErrorAt(scene, "objects[0].radius", "a number in (0, 1000000000], found a string \"big\"");
}

// An index the float32 fields cannot hold apart from 0 (1e-300 was refused
// later, at a field cell) is refused at its key path.
TEST(SceneParserErrors, IndexOutsideWhatTheFieldsHold) {
    json scene = validScene();
    scene["objects"][1]["index"] = 0;
    expectErrorAt(scene, "objects[1].index", "a number in [0.001, 1000], found 0");
    scene["objects"][1]["index"] = 1e-300;
    expectErrorAt(scene, "objects[1].index", "a number in [0.001, 1000], found 1e-300");
}

TEST(SceneParserErrors, MissingRequiredKey) {
    json scene = validScene();
    scene["objects"][0].erase("index");
    expectErrorAt(scene, "objects[0].index", "found nothing");
}

TEST(SceneParserErrors, NegativeExtinction) {
    json scene = validScene();
    scene["medium"]["extinction"] = {0.1, -0.25, 0};
    expectErrorAt(scene, "medium.extinction[1]", "a number in [0, 1e+30], found -0.25");
}

TEST(SceneParserErrors, ScatteringAboveExtinction) {
    json scene = validScene();
    scene["objects"][0]["scattering"] = 0.25;
    expectErrorAt(scene, "objects[0].scattering", "scattering <= extinction [0.1, 0.2, 0.3]");
}

TEST(SceneParserErrors, ZeroResolution) {
    json scene = validScene();
    scene["grid"]["resolution"][2] = 0;
    expectErrorAt(scene, "grid.resolution[2]", "an integer in [1, ");
}

TEST(SceneParserErrors, NonIntegerResolution) {
    json scene = validScene();
    scene["grid"]["resolution"][0] = 2.5;
    expectErrorAt(scene, "grid.resolution[0]", "found 2.5");
}

TEST(SceneParserErrors, TooManyGridCells) {
    json scene = validScene();
    scene["grid"]["resolution"] = {1024, 1024, 1024};
    expectErrorAt(scene, "grid.resolution", "at most 134217728 cells");
}

TEST(SceneParserErrors, EmptyBounds) {
    json scene = validScene();
    scene["grid"]["bounds"]["max"][1] = -0.5;  // equals min[1]
    expectErrorAt(scene, "grid.bounds.max[1]", "grid.bounds.min[1] = -0.5");
}

TEST(SceneParserErrors, InvertedBox) {
    json scene = validScene();
    scene["objects"][1]["max"][0] = -1;
    expectErrorAt(scene, "objects[1].max[0]", "objects[1].min[0]");
}

TEST(SceneParserErrors, NonFiniteNumber) {
    json scene = validScene();
    scene["lights"][0]["position"][1] = std::numeric_limits<double>::infinity();
    expectErrorAt(scene, "lights[0].position[1]", "found a number too large to represent (inf)");
    scene["lights"][0]["position"][1] = std::nan("");
    expectErrorAt(scene, "lights[0].position[1]", "(nan)");
}

TEST(SceneParserErrors, WrongVectorLength) {
    json scene = validScene();
    scene["camera"]["position"] = {1, 2};
    expectErrorAt(scene, "camera.position", "an array of 3 numbers, found an array of 2 elements");
}

TEST(SceneParserErrors, UnknownObjectType) {
    json scene = validScene();
    scene["objects"][1]["type"] = "cone";
    expectErrorAt(scene, "objects[1].type", "one of \"sphere\", \"box\", \"mesh\", \"water\", found a string \"cone\"");
}

TEST(SceneParserErrors, UnknownLightType) {
    json scene = validScene();
    scene["lights"][0]["type"] = "area";
    expectErrorAt(scene, "lights[0].type", "one of \"point\", \"spot\", \"directional\", found a string \"area\"");
}

TEST(SceneParserErrors, MissingLights) {
    json scene = validScene();
    scene.erase("lights");
    expectErrorAt(scene, "lights", "at least one light (or a volume with emission_lights), found nothing");
    scene["lights"] = json::array();
    expectErrorAt(scene, "lights", "found an array of 0 elements");
}

TEST(SceneParserErrors, ZeroNormal) {
    json scene = validScene();
    scene["receivers"][1]["normal"] = {0, 0, 0};
    expectErrorAt(scene, "receivers[1].normal", "a non-zero vector");
}

TEST(SceneParserErrors, AlbedoAboveOne) {
    json scene = validScene();
    scene["receivers"][1]["albedo"] = 1.5;
    expectErrorAt(scene, "receivers[1].albedo", "a number in [0, 1], found 1.5");
}

TEST(SceneParserErrors, FieldOfViewOutOfRange) {
    json scene = validScene();
    scene["camera"]["fov_deg"] = 180;
    expectErrorAt(scene, "camera.fov_deg", "a number in (0, 180), found 180");
}

TEST(SceneParserErrors, SamplesPerPixelIsASquareUpTo1024) {
    json scene = validScene();
    scene["render"]["samples_per_pixel"] = 8;
    expectErrorAt(scene, "render.samples_per_pixel",
                  "a square number (the rays pass through a k × k grid of the pixel): 1, 4, 9, 16, ..., found 8");
    scene["render"]["samples_per_pixel"] = 0;
    expectErrorAt(scene, "render.samples_per_pixel", "an integer in [1, 1024], found 0");
    scene["render"]["samples_per_pixel"] = 1089;
    expectErrorAt(scene, "render.samples_per_pixel", "an integer in [1, 1024], found 1089");
    scene["render"]["samples_per_pixel"] = 9;
    EXPECT_EQ(parseScene(scene, "scene.json").render.samplesPerPixel, 9);
}

TEST(SceneParserErrors, CameraTargetAtPosition) {
    json scene = validScene();
    scene["camera"]["target"] = {0, 1, 4};
    expectErrorAt(scene, "camera.target", "a point other than camera.position");
}

TEST(SceneParserErrors, CameraUpAlongView) {
    json scene = validScene();
    scene["camera"]["up"] = {0, -2, -8};
    expectErrorAt(scene, "camera.up", "not parallel");
}

TEST(SceneParserErrors, TooManyPhotons) {
    json scene = validScene();
    scene["render"]["photons"] = 4294967296LL;
    expectErrorAt(scene, "render.photons", "an integer in [1, 2147483647]");
}

TEST(SceneParserErrors, EvenSmoothingWindow) {
    json scene = sceneWithNewKeys();
    scene["grid"]["smoothing_window_voxels"] = 8;
    expectErrorAt(scene, "grid.smoothing_window_voxels", "an odd integer in [1, 63]");
    expectErrorAt(scene, "grid.smoothing_window_voxels", "found 8");
}

TEST(SceneParserErrors, SmoothingWindowOutOfRange) {
    json scene = sceneWithNewKeys();
    scene["grid"]["smoothing_window_voxels"] = 0;  // automatic is spelt by leaving the key out
    expectErrorAt(scene, "grid.smoothing_window_voxels", "an integer in [1, 63], found 0");
    scene["grid"]["smoothing_window_voxels"] = 65;
    expectErrorAt(scene, "grid.smoothing_window_voxels", "found 65");
}

TEST(SceneParserErrors, SpotFalloffBeyondCone) {
    json scene = sceneWithNewKeys();
    scene["lights"][2]["falloff_deg"] = 50;
    expectErrorAt(scene, "lights[2].falloff_deg", "a number in [0, lights[2].cone_angle_deg = 45]");
    expectErrorAt(scene, "lights[2].falloff_deg", "found 50");
    scene["lights"][2].erase("cone_angle_deg");  // against the default cone
    scene["lights"][2]["falloff_deg"] = 31;
    expectErrorAt(scene, "lights[2].falloff_deg", "lights[2].cone_angle_deg = 30]");
    scene["lights"][2]["falloff_deg"] = -1;
    expectErrorAt(scene, "lights[2].falloff_deg", "a number >= 0, found -1");
}

TEST(SceneParserErrors, SpotConeAngleOutOfRange) {
    json scene = sceneWithNewKeys();
    scene["lights"][2]["cone_angle_deg"] = 0;
    expectErrorAt(scene, "lights[2].cone_angle_deg", "a number in (0, 180), found 0");
    scene["lights"][2]["cone_angle_deg"] = 180;
    expectErrorAt(scene, "lights[2].cone_angle_deg", "found 180");
}

TEST(SceneParserErrors, SpotNeedsANonZeroDirection) {
    json scene = sceneWithNewKeys();
    scene["lights"][2]["direction"] = {0, 0, 0};
    expectErrorAt(scene, "lights[2].direction", "a non-zero vector");
    scene["lights"][2].erase("direction");
    expectErrorAt(scene, "lights[2].direction", "found nothing");
}

TEST(SceneParserErrors, SpotKeyOnAPointLight) {
    json scene = validScene();
    scene["lights"][0]["cone_angle_deg"] = 20;
    expectErrorAt(scene, "lights[0].cone_angle_deg", "found an unknown key");
}

TEST(SceneParserErrors, UnknownIntegrator) {
    json scene = sceneWithNewKeys();
    scene["tracer"]["integrator"] = "verlet";
    expectErrorAt(scene, "tracer.integrator", "one of \"euler\", \"leapfrog\", \"rk4\", found a string \"verlet\"");
}

TEST(SceneParserErrors, UnknownStepPolicy) {
    json scene = sceneWithNewKeys();
    scene["tracer"]["step_policy"] = "adaptive";
    expectErrorAt(scene, "tracer.step_policy", "one of \"uniform\", \"octree\"");
}

TEST(SceneParserErrors, MaxStepBelowStep) {
    json scene = sceneWithNewKeys();
    scene["tracer"]["max_step_voxels"] = 0.125;
    expectErrorAt(scene, "tracer.max_step_voxels", "a number >= tracer.step_voxels = 0.25, found 0.125");
    scene["tracer"].erase("step_voxels");  // against the default step
    scene["tracer"]["max_step_voxels"] = 0.25;
    expectErrorAt(scene, "tracer.max_step_voxels", "tracer.step_voxels = 0.5");
}

TEST(SceneParserErrors, EpsilonPrimeBelowEpsilon) {
    json scene = sceneWithNewKeys();
    scene["tracer"]["epsilon_prime"] = 0.0005;
    expectErrorAt(scene, "tracer.epsilon_prime", "a number >= tracer.epsilon = 0.001, found 0.0005");
}

TEST(SceneParserErrors, NonPositiveStepOrEpsilon) {
    json scene = sceneWithNewKeys();
    scene["tracer"]["step_voxels"] = 0;
    expectErrorAt(scene, "tracer.step_voxels", "a number > 0, found 0");
    scene = sceneWithNewKeys();
    scene["tracer"]["epsilon"] = -0.01;
    expectErrorAt(scene, "tracer.epsilon", "a number > 0, found -0.01");
}

TEST(SceneParserErrors, PowerCutoffOfOne) {
    json scene = sceneWithNewKeys();
    scene["tracer"]["power_cutoff"] = 1;
    expectErrorAt(scene, "tracer.power_cutoff", "a number in [0, 1), found 1");
}

TEST(SceneParserErrors, MissingEnvironmentImage) {
    json scene = validScene();
    scene["render"].erase("background");
    scene["render"]["environment"] = {{"type", "hdr"}, {"path", "no/such/sky.hdr"}};
    expectErrorAt(scene, "render.environment.path", "which does not exist");
}

TEST(SceneParser, ReceiverBounceIsReadAndDefaultsToStopping) {
    json scene = validScene();
    EXPECT_FALSE(parseScene(scene, "test.json").receivers[0].bounce);
    scene["receivers"][0]["bounce"] = true;
    EXPECT_TRUE(parseScene(scene, "test.json").receivers[0].bounce);
    scene["receivers"][0]["bounce"] = "yes";
    expectErrorAt(scene, "receivers[0].bounce", "expected true or false");
}

TEST(SceneParserErrors, BooleanGivenAsNumberOrString) {
    json scene = sceneWithNewKeys();
    scene["tracer"]["renormalize"] = 1;
    expectErrorAt(scene, "tracer.renormalize", "expected true or false, found 1");
    scene["tracer"]["renormalize"] = false;
    scene["tracer"]["store_fluence"] = "true";
    expectErrorAt(scene, "tracer.store_fluence", "expected true or false, found a string \"true\"");
}

TEST(SceneParserErrors, ZeroDispersion) {
    json scene = sceneWithNewKeys();
    scene["tracer"]["dispersion"] = {1, 0, 1};
    expectErrorAt(scene, "tracer.dispersion[1]", "a number > 0, found 0");
    scene["tracer"]["dispersion"] = 0;
    expectErrorAt(scene, "tracer.dispersion", "a number > 0, found 0");
}

TEST(SceneParserErrors, MaxStepsOutOfRange) {
    json scene = sceneWithNewKeys();
    scene["tracer"]["max_steps"] = -1;
    expectErrorAt(scene, "tracer.max_steps", "an integer in [0, 2147483647], found -1");
    scene["tracer"]["max_steps"] = 2147483648LL;
    expectErrorAt(scene, "tracer.max_steps", "found 2147483648");
    scene["tracer"]["max_steps"] = 10.5;
    expectErrorAt(scene, "tracer.max_steps", "found 10.5");
}

TEST(SceneParserErrors, UnknownTracerKey) {
    json scene = sceneWithNewKeys();
    scene["tracer"]["stepvoxels"] = 1;
    expectErrorAt(scene, "tracer.stepvoxels", "\"step_voxels\"");
    scene = validScene();
    scene["tracer"] = "rk4";
    expectErrorAt(scene, "tracer", "an object, found a string \"rk4\"");
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
