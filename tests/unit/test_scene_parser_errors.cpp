// Bad values in a scene file, each refused with an InputError at its JSON
// path whose message says what was expected and what was found: one
// parameterised test over a table of edits to a valid scene.
#include "bridge/core/Error.h"
#include "tests/unit/SceneParserTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace eikon {
namespace {

using namespace test;

struct BadValue {
    const char* name;
    json (*base)();              // validScene or sceneWithNewKeys
    void (*edit)(json& scene);  // what makes it bad
    const char* path;            // where the error must point
    const char* detail;          // a part of its message
};

std::vector<BadValue> badValues() {
    return {
        {"UnknownTopLevelKey", validScene,
         [](json& scene) {
             scene["lightz"] = json::array();
         },
         "lightz", "\"lights\""},
        {"AnisotropyFloatRoundsToOne", validScene,
         [](json& scene) {
             scene["medium"]["anisotropy"] = 0.9999999999;
         },
         "medium.anisotropy", "0.99999"},
        {"PowerWhoseTalliesOverflow", validScene,
         [](json& scene) {
             scene["lights"][0]["power"] = 1e308;
         },
         "lights[0].power", "1e+30"},
        {"BoundsWhoseExtentOverflows", validScene,
         [](json& scene) {
             scene["grid"]["bounds"]["max"][0] = 1e308;
         },
         "grid.bounds.max[0]", "1000000000]"},
        {"UnknownNestedKey", validScene,
         [](json& scene) {
             scene["objects"][0].erase("radius");
             scene["objects"][0]["radus"] = 0.4;
         },
         "objects[0].radus", "found an unknown key"},
        {"KeyOfAnotherObjectType", validScene,
         [](json& scene) {
             scene["objects"][1]["radius"] = 0.4;  // objects[1] is a box
         },
         "objects[1].radius", "\"min\", \"max\""},
        {"StringForANumber", validScene,
         [](json& scene) {
             scene["objects"][0]["radius"] = "big";
         },
         "objects[0].radius", "a number in (0, 1000000000], found a string \"big\""},
        {"IndexOfZero", validScene,
         [](json& scene) {
             scene["objects"][1]["index"] = 0;
         },
         "objects[1].index", "a number in [0.001, 1000], found 0"},
        {"IndexFloatCannotTellFromZero", validScene,
         [](json& scene) {
             scene["objects"][1]["index"] = 1e-300;
         },
         "objects[1].index", "a number in [0.001, 1000], found 1e-300"},
        {"MissingRequiredKey", validScene,
         [](json& scene) {
             scene["objects"][0].erase("index");
         },
         "objects[0].index", "found nothing"},
        {"NegativeExtinction", validScene,
         [](json& scene) {
             scene["medium"]["extinction"] = {0.1, -0.25, 0};
         },
         "medium.extinction[1]", "a number in [0, 1e+30], found -0.25"},
        {"ScatteringAboveExtinction", validScene,
         [](json& scene) {
             scene["objects"][0]["scattering"] = 0.25;
         },
         "objects[0].scattering", "scattering <= extinction [0.1, 0.2, 0.3]"},
        {"ZeroResolution", validScene,
         [](json& scene) {
             scene["grid"]["resolution"][2] = 0;
         },
         "grid.resolution[2]", "an integer in [1, "},
        {"NonIntegerResolution", validScene,
         [](json& scene) {
             scene["grid"]["resolution"][0] = 2.5;
         },
         "grid.resolution[0]", "found 2.5"},
        {"TooManyGridCells", validScene,
         [](json& scene) {
             scene["grid"]["resolution"] = {1024, 1024, 1024};
         },
         "grid.resolution", "at most 134217728 cells"},
        {"EmptyBounds", validScene,
         [](json& scene) {
             scene["grid"]["bounds"]["max"][1] = -0.5;  // equals min[1]
         },
         "grid.bounds.max[1]", "grid.bounds.min[1] = -0.5"},
        {"InvertedBox", validScene,
         [](json& scene) {
             scene["objects"][1]["max"][0] = -1;
         },
         "objects[1].max[0]", "objects[1].min[0]"},
        {"InfiniteNumber", validScene,
         [](json& scene) {
             scene["lights"][0]["position"][1] = std::numeric_limits<double>::infinity();
         },
         "lights[0].position[1]", "found a number too large to represent (inf)"},
        {"NanNumber", validScene,
         [](json& scene) {
             scene["lights"][0]["position"][1] = std::nan("");
         },
         "lights[0].position[1]", "(nan)"},
        {"WrongVectorLength", validScene,
         [](json& scene) {
             scene["camera"]["position"] = {1, 2};
         },
         "camera.position", "an array of 3 numbers, found an array of 2 elements"},
        {"UnknownObjectType", validScene,
         [](json& scene) {
             scene["objects"][1]["type"] = "cone";
         },
         "objects[1].type", "one of \"sphere\", \"box\", \"mesh\", \"water\", found a string \"cone\""},
        {"UnknownLightType", validScene,
         [](json& scene) {
             scene["lights"][0]["type"] = "area";
         },
         "lights[0].type", "one of \"point\", \"spot\", \"directional\", found a string \"area\""},
        {"MissingLights", validScene,
         [](json& scene) {
             scene.erase("lights");
         },
         "lights", "at least one light (or a volume with emission_lights), found nothing"},
        {"NoLights", validScene,
         [](json& scene) {
             scene["lights"] = json::array();
         },
         "lights", "found an array of 0 elements"},
        {"ZeroNormal", validScene,
         [](json& scene) {
             scene["receivers"][1]["normal"] = {0, 0, 0};
         },
         "receivers[1].normal", "a non-zero vector"},
        {"AlbedoAboveOne", validScene,
         [](json& scene) {
             scene["receivers"][1]["albedo"] = 1.5;
         },
         "receivers[1].albedo", "a number in [0, 1], found 1.5"},
        {"ReceiverBounceNotABoolean", validScene,
         [](json& scene) {
             scene["receivers"][0]["bounce"] = "yes";
         },
         "receivers[0].bounce", "expected true or false"},
        {"FieldOfViewOutOfRange", validScene,
         [](json& scene) {
             scene["camera"]["fov_deg"] = 180;
         },
         "camera.fov_deg", "a number in (0, 180), found 180"},
        {"SamplesPerPixelNotASquare", validScene,
         [](json& scene) {
             scene["render"]["samples_per_pixel"] = 8;
         },
         "render.samples_per_pixel", "a square number (the rays pass through a k × k grid of the pixel): 1, 4, 9, 16, ..., found 8"},
        {"NoSamplesPerPixel", validScene,
         [](json& scene) {
             scene["render"]["samples_per_pixel"] = 0;
         },
         "render.samples_per_pixel", "an integer in [1, 1024], found 0"},
        {"SamplesPerPixelAbove1024", validScene,
         [](json& scene) {
             scene["render"]["samples_per_pixel"] = 1089;
         },
         "render.samples_per_pixel", "an integer in [1, 1024], found 1089"},
        {"CameraTargetAtPosition", validScene,
         [](json& scene) {
             scene["camera"]["target"] = {0, 1, 4};
         },
         "camera.target", "a point other than camera.position"},
        {"CameraUpAlongView", validScene,
         [](json& scene) {
             scene["camera"]["up"] = {0, -2, -8};
         },
         "camera.up", "not parallel"},
        {"TooManyPhotons", validScene,
         [](json& scene) {
             scene["render"]["photons"] = 4294967296LL;
         },
         "render.photons", "an integer in [1, 2147483647]"},
        {"RenderDeviceUnknown", validScene,
         [](json& scene) {
             scene["render"]["device"] = "native";
         },
         "render.device", "one of"},
        {"EvenSmoothingWindow", sceneWithNewKeys,
         [](json& scene) {
             scene["grid"]["smoothing_window_voxels"] = 8;
         },
         "grid.smoothing_window_voxels", "an odd integer in [1, 63]"},
        {"EvenSmoothingWindowFound", sceneWithNewKeys,
         [](json& scene) {
             scene["grid"]["smoothing_window_voxels"] = 8;
         },
         "grid.smoothing_window_voxels", "found 8"},
        {"SmoothingWindowOfZero", sceneWithNewKeys,
         [](json& scene) {
             scene["grid"]["smoothing_window_voxels"] = 0;  // automatic is spelt by leaving the key out
         },
         "grid.smoothing_window_voxels", "an integer in [1, 63], found 0"},
        {"SmoothingWindowAbove63", sceneWithNewKeys,
         [](json& scene) {
             scene["grid"]["smoothing_window_voxels"] = 65;
         },
         "grid.smoothing_window_voxels", "found 65"},
        {"SpotFalloffBeyondCone", sceneWithNewKeys,
         [](json& scene) {
             scene["lights"][2]["falloff_deg"] = 50;
         },
         "lights[2].falloff_deg", "a number in [0, lights[2].cone_angle_deg = 45]"},
        {"SpotFalloffBeyondConeFound", sceneWithNewKeys,
         [](json& scene) {
             scene["lights"][2]["falloff_deg"] = 50;
         },
         "lights[2].falloff_deg", "found 50"},
        {"SpotFalloffBeyondDefaultCone", sceneWithNewKeys,
         [](json& scene) {
             scene["lights"][2].erase("cone_angle_deg");  // against the default cone
             scene["lights"][2]["falloff_deg"] = 31;
         },
         "lights[2].falloff_deg", "lights[2].cone_angle_deg = 30]"},
        {"SpotFalloffNegative", sceneWithNewKeys,
         [](json& scene) {
             scene["lights"][2].erase("cone_angle_deg");
             scene["lights"][2]["falloff_deg"] = -1;
         },
         "lights[2].falloff_deg", "a number >= 0, found -1"},
        {"SpotConeAngleOfZero", sceneWithNewKeys,
         [](json& scene) {
             scene["lights"][2]["cone_angle_deg"] = 0;
         },
         "lights[2].cone_angle_deg", "a number in (0, 180), found 0"},
        {"SpotConeAngleOf180", sceneWithNewKeys,
         [](json& scene) {
             scene["lights"][2]["cone_angle_deg"] = 180;
         },
         "lights[2].cone_angle_deg", "found 180"},
        {"SpotZeroDirection", sceneWithNewKeys,
         [](json& scene) {
             scene["lights"][2]["direction"] = {0, 0, 0};
         },
         "lights[2].direction", "a non-zero vector"},
        {"SpotWithoutDirection", sceneWithNewKeys,
         [](json& scene) {
             scene["lights"][2].erase("direction");
         },
         "lights[2].direction", "found nothing"},
        {"SpotKeyOnAPointLight", validScene,
         [](json& scene) {
             scene["lights"][0]["cone_angle_deg"] = 20;
         },
         "lights[0].cone_angle_deg", "found an unknown key"},
        {"UnknownIntegrator", sceneWithNewKeys,
         [](json& scene) {
             scene["tracer"]["integrator"] = "verlet";
         },
         "tracer.integrator", "one of \"euler\", \"leapfrog\", \"rk4\", found a string \"verlet\""},
        {"UnknownStepPolicy", sceneWithNewKeys,
         [](json& scene) {
             scene["tracer"]["step_policy"] = "adaptive";
         },
         "tracer.step_policy", "one of \"uniform\", \"octree\""},
        {"MaxStepBelowStep", sceneWithNewKeys,
         [](json& scene) {
             scene["tracer"]["max_step_voxels"] = 0.125;
         },
         "tracer.max_step_voxels", "a number >= tracer.step_voxels = 0.25, found 0.125"},
        {"MaxStepBelowDefaultStep", sceneWithNewKeys,
         [](json& scene) {
             scene["tracer"].erase("step_voxels");  // against the default step
             scene["tracer"]["max_step_voxels"] = 0.25;
         },
         "tracer.max_step_voxels", "tracer.step_voxels = 0.5"},
        {"EpsilonPrimeBelowEpsilon", sceneWithNewKeys,
         [](json& scene) {
             scene["tracer"]["epsilon_prime"] = 0.0005;
         },
         "tracer.epsilon_prime", "a number >= tracer.epsilon = 0.001, found 0.0005"},
        {"ZeroStep", sceneWithNewKeys,
         [](json& scene) {
             scene["tracer"]["step_voxels"] = 0;
         },
         "tracer.step_voxels", "a number > 0, found 0"},
        {"NegativeEpsilon", sceneWithNewKeys,
         [](json& scene) {
             scene["tracer"]["epsilon"] = -0.01;
         },
         "tracer.epsilon", "a number > 0, found -0.01"},
        {"PowerCutoffOfOne", sceneWithNewKeys,
         [](json& scene) {
             scene["tracer"]["power_cutoff"] = 1;
         },
         "tracer.power_cutoff", "a number in [0, 1), found 1"},
        {"MissingEnvironmentImage", validScene,
         [](json& scene) {
             scene["render"].erase("background");
             scene["render"]["environment"] = {{"type", "hdr"}, {"path", "no/such/sky.hdr"}};
         },
         "render.environment.path", "which does not exist"},
        {"BooleanGivenAsNumber", sceneWithNewKeys,
         [](json& scene) {
             scene["tracer"]["renormalize"] = 1;
         },
         "tracer.renormalize", "expected true or false, found 1"},
        {"BooleanGivenAsString", sceneWithNewKeys,
         [](json& scene) {
             scene["tracer"]["store_fluence"] = "true";
         },
         "tracer.store_fluence", "expected true or false, found a string \"true\""},
        {"ZeroDispersionChannel", sceneWithNewKeys,
         [](json& scene) {
             scene["tracer"]["dispersion"] = {1, 0, 1};
         },
         "tracer.dispersion[1]", "a number > 0, found 0"},
        {"ZeroDispersion", sceneWithNewKeys,
         [](json& scene) {
             scene["tracer"]["dispersion"] = 0;
         },
         "tracer.dispersion", "a number > 0, found 0"},
        {"NegativeMaxSteps", sceneWithNewKeys,
         [](json& scene) {
             scene["tracer"]["max_steps"] = -1;
         },
         "tracer.max_steps", "an integer in [0, 2147483647], found -1"},
        {"MaxStepsAboveInt", sceneWithNewKeys,
         [](json& scene) {
             scene["tracer"]["max_steps"] = 2147483648LL;
         },
         "tracer.max_steps", "found 2147483648"},
        {"FractionalMaxSteps", sceneWithNewKeys,
         [](json& scene) {
             scene["tracer"]["max_steps"] = 10.5;
         },
         "tracer.max_steps", "found 10.5"},
        {"UnknownTracerKey", sceneWithNewKeys,
         [](json& scene) {
             scene["tracer"]["stepvoxels"] = 1;
         },
         "tracer.stepvoxels", "\"step_voxels\""},
        {"TracerNotAnObject", validScene,
         [](json& scene) {
             scene["tracer"] = "rk4";
         },
         "tracer", "an object, found a string \"rk4\""},
        {"MultipleScatteringUnknown", validScene,
         [](json& scene) {
             scene["tracer"] = {{"multiple_scattering", "diffusion"}};
         },
         "tracer.multiple_scattering", "\"lbm\""},
        {"LatticeDirectionsOf12", validScene,
         [](json& scene) {
             scene["tracer"] = {{"lbm_directions", 12}};
         },
         "tracer.lbm_directions", "6, 14 or 18"},
        {"LatticeDirectionsOf26", validScene,
         [](json& scene) {
             scene["tracer"] = {{"lbm_directions", 26}};
         },
         "tracer.lbm_directions", "18"},
        {"LatticeToleranceOfZero", validScene,
         [](json& scene) {
             scene["tracer"] = {{"lbm_tolerance", 0}};
         },
         "tracer.lbm_tolerance", "(0, 1)"},
        {"LatticeToleranceOfOne", validScene,
         [](json& scene) {
             scene["tracer"] = {{"lbm_tolerance", 1}};
         },
         "tracer.lbm_tolerance", "(0, 1)"},
        {"NoLatticeIterations", validScene,
         [](json& scene) {
             scene["tracer"] = {{"lbm_max_iterations", 0}};
         },
         "tracer.lbm_max_iterations", ""},
    };
}

class SceneParserErrors : public ::testing::TestWithParam<BadValue> {};

TEST_P(SceneParserErrors, RefusedAtTheirPath) {
    json scene = GetParam().base();
    GetParam().edit(scene);
    expectErrorAt(scene, GetParam().path, GetParam().detail);
}

INSTANTIATE_TEST_SUITE_P(SceneParser, SceneParserErrors, ::testing::ValuesIn(badValues()),
                         [](const ::testing::TestParamInfo<BadValue>& row) { return std::string(row.param.name); });

}  // namespace
}  // namespace eikon
