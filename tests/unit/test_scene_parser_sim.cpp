// The `sim` section of scene files.
#include "io/scene/SceneParser.h"

#include "bridge/core/Error.h"
#include "tests/unit/SceneParserTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <string>

namespace eikon {
namespace {

using namespace test;

json sceneWithSim(const json& sim) {
    json root = validScene();
    root["sim"] = sim;
    return root;
}

const char* const kValidSim = R"({
  "fluid": "liquid", "resolution": [24, 32, 16],
  "bounds": {"min": [-0.2, 0, -0.1], "max": [0.2, 0.5, 0.1]},
  "frame_time": 0.02, "substeps": 3, "max_substeps": 500, "cfl": 1.5, "gravity": [0, -9.8, 0],
  "thermal_expansion": 3e-4, "concentration_expansion": 0.2, "viscosity": 2e-6,
  "thermal_diffusivity": 1.5e-7, "concentration_diffusivity": 1e-9, "dye_diffusivity": 1e-8,
  "pressure_tolerance": 1e-5, "vorticity_confinement": 0.8, "device": "gpu",
  "boundaries": {"y_max": "open", "x_min": "closed"},
  "obstacles": [{"type": "box", "min": [-0.05, 0, -0.05], "max": [0.05, 0.1, 0.05]},
                {"type": "sphere", "center": [0, 0.3, 0], "radius": 0.04}],
  "sources": [{"type": "hot_plate", "min": [-0.1, 0, -0.1], "max": [0.1, 0.02, 0.1], "temperature": 330},
              {"type": "jet", "min": [-0.02, 0.4, -0.02], "max": [0.02, 0.45, 0.02], "velocity": [0, -0.1, 0],
               "concentration": 0.8, "dye": 2}],
  "ambient_temperature": 290, "ambient_pressure": 100000,
  "optics": {"index_a": 1.33, "index_b": 1.45, "mixing": "lorentz_lorenz",
             "refractivity": 2.9e-4, "reference_temperature": 273, "reference_pressure": 100000,
             "dye_extinction": [3, 2, 1], "dye_scattering": [1, 1, 0.5]}
})";

TEST(SceneParserSim, ParsesEverySimKey) {
    const Scene scene = parseScene(sceneWithSim(json::parse(kValidSim)), "test.json");
    ASSERT_TRUE(scene.sim.has_value());
    const SimDesc& sim = *scene.sim;
    EXPECT_EQ(sim.fluid, SimDesc::Fluid::Liquid);
    EXPECT_EQ(sim.resolution, glm::ivec3(24, 32, 16));
    EXPECT_EQ(sim.device, SimDesc::Device::Gpu);
    ASSERT_TRUE(sim.bounds.has_value());
    EXPECT_EQ(sim.bounds->min, glm::dvec3(-0.2, 0, -0.1));
    EXPECT_EQ(sim.bounds->max, glm::dvec3(0.2, 0.5, 0.1));
    EXPECT_DOUBLE_EQ(sim.frameTime, 0.02);
    EXPECT_EQ(sim.substeps, 3);
    EXPECT_EQ(sim.maxSubsteps, 500);
    EXPECT_DOUBLE_EQ(sim.cfl, 1.5);
    EXPECT_EQ(sim.gravity, glm::dvec3(0, -9.8, 0));
    EXPECT_DOUBLE_EQ(sim.thermalExpansion, 3e-4);
    EXPECT_DOUBLE_EQ(sim.concentrationExpansion, 0.2);
    EXPECT_DOUBLE_EQ(sim.viscosity, 2e-6);
    EXPECT_DOUBLE_EQ(sim.thermalDiffusivity, 1.5e-7);
    EXPECT_DOUBLE_EQ(sim.concentrationDiffusivity, 1e-9);
    EXPECT_DOUBLE_EQ(sim.dyeDiffusivity, 1e-8);
    EXPECT_DOUBLE_EQ(sim.pressureTolerance, 1e-5);
    EXPECT_DOUBLE_EQ(sim.vorticityConfinement, 0.8);
    EXPECT_EQ(sim.boundaries[3], SimDesc::Boundary::Open);
    for (int face : {0, 1, 2, 4, 5}) EXPECT_EQ(sim.boundaries[face], SimDesc::Boundary::Closed) << face;
    ASSERT_EQ(sim.obstacles.size(), 2u);
    EXPECT_EQ(sim.obstacles[0].kind, SimDesc::Obstacle::Kind::Box);
    EXPECT_EQ(sim.obstacles[0].box.max, glm::dvec3(0.05, 0.1, 0.05));
    EXPECT_EQ(sim.obstacles[1].kind, SimDesc::Obstacle::Kind::Sphere);
    EXPECT_DOUBLE_EQ(sim.obstacles[1].sphere.radius, 0.04);
    ASSERT_EQ(sim.sources.size(), 2u);
    EXPECT_EQ(sim.sources[0].kind, SimDesc::Source::Kind::HotPlate);
    EXPECT_DOUBLE_EQ(sim.sources[0].temperature, 330.0);
    EXPECT_EQ(sim.sources[1].kind, SimDesc::Source::Kind::Jet);
    EXPECT_EQ(sim.sources[1].velocity, glm::dvec3(0, -0.1, 0));
    EXPECT_DOUBLE_EQ(sim.sources[1].concentration, 0.8);
    EXPECT_DOUBLE_EQ(sim.sources[1].dye, 2.0);
    EXPECT_EQ(sim.sources[1].region.min, glm::dvec3(-0.02, 0.4, -0.02));
    EXPECT_DOUBLE_EQ(sim.ambientTemperature, 290.0);
    EXPECT_DOUBLE_EQ(sim.ambientPressure, 100000.0);
    EXPECT_DOUBLE_EQ(sim.indexA, 1.33);
    EXPECT_DOUBLE_EQ(sim.indexB, 1.45);
    EXPECT_EQ(sim.mixing, SimDesc::Mixing::LorentzLorenz);
    EXPECT_DOUBLE_EQ(sim.refractivity, 2.9e-4);
    EXPECT_DOUBLE_EQ(sim.referenceTemperature, 273.0);
    EXPECT_DOUBLE_EQ(sim.referencePressure, 100000.0);
    EXPECT_EQ(sim.dyeExtinction, Rgb(3, 2, 1));
    EXPECT_EQ(sim.dyeScattering, Rgb(1, 1, 0.5));
}

TEST(SceneParserSim, AbsentSimAndFluidDefaults) {
    EXPECT_FALSE(parseScene(validScene(), "test.json").sim.has_value());

    const SimDesc air = *parseScene(sceneWithSim(json::object({{"ambient_temperature", 300}})), "test.json").sim;
    EXPECT_EQ(air.fluid, SimDesc::Fluid::Air);
    EXPECT_EQ(air.resolution, glm::ivec3(32));
    EXPECT_FALSE(air.bounds.has_value());  // the render grid's
    EXPECT_DOUBLE_EQ(air.thermalExpansion, 1.0 / 300.0);  // ideal gas: 1/T_ambient
    EXPECT_DOUBLE_EQ(air.viscosity, 1.5e-5);
    EXPECT_DOUBLE_EQ(air.concentrationExpansion, 0.0);
    EXPECT_DOUBLE_EQ(air.pressureTolerance, 1e-6);
    EXPECT_DOUBLE_EQ(air.vorticityConfinement, 0.0);  // off
    EXPECT_EQ(air.maxSubsteps, 1000);
    // A minimum above the default limit raises the limit with it.
    EXPECT_EQ(parseScene(sceneWithSim(json::object({{"substeps", 5000}})), "test.json").sim->maxSubsteps, 5000);
    EXPECT_EQ(air.mixing, SimDesc::Mixing::Linear);
    EXPECT_DOUBLE_EQ(air.refractivity, 2.93e-4);

    const SimDesc liquid = *parseScene(sceneWithSim(json::object({{"fluid", "liquid"}})), "test.json").sim;
    EXPECT_DOUBLE_EQ(liquid.thermalExpansion, 2.07e-4);
    EXPECT_DOUBLE_EQ(liquid.concentrationExpansion, 0.289);
    EXPECT_DOUBLE_EQ(liquid.viscosity, 1.0e-6);
    EXPECT_DOUBLE_EQ(liquid.indexA, 1.333);
    EXPECT_DOUBLE_EQ(liquid.indexB, 1.4418);
}

TEST(SceneParserSim, BadValuesNameTheirJsonPath) {
    struct Case {
        const char* key;
        json value;
        const char* path;
        const char* detail;
    };
    const Case cases[] = {
        {"fluid", "water", "sim.fluid", "one of"},
        {"device", "cuda", "sim.device", "one of"},
        {"resolution", json::array({0, 8, 8}), "sim.resolution[0]", "an integer in [1, "},
        {"frame_time", 0, "sim.frame_time", "a number > 0"},
        {"substeps", 2.5, "sim.substeps", "an integer in [1, 10000]"},
        {"cfl", -1, "sim.cfl", "a number > 0"},
        {"max_substeps", 0, "sim.max_substeps", "an integer in [1, 1000000]"},
        {"max_substeps", 1e7, "sim.max_substeps", "an integer in [1, 1000000]"},
        {"viscosity", -1e-6, "sim.viscosity", "a number >= 0"},
        {"vorticity_confinement", -0.1, "sim.vorticity_confinement", "a number >= 0"},
        {"pressure_tolerance", 1, "sim.pressure_tolerance", "a number in (0, 1)"},
        {"boundaries", json::object({{"y_max", "leaky"}}), "sim.boundaries.y_max", "one of"},
        {"boundaries", json::object({{"top", "open"}}), "sim.boundaries.top", "one of the keys"},
        {"obstacles", json::array({json::object({{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 0}})}),
         "sim.obstacles[0].radius", "a number in (0, 1000000000]"},
        {"sources", json::array({json::object({{"type", "jet"}, {"min", {0, 0, 0}}, {"max", {1, 0, 1}}, {"velocity", {0, 1, 0}}})}),
         "sim.sources[0].max[1]", "the bounds must not be empty"},
        {"sources", json::array({json::object({{"type", "hot_plate"}, {"min", {0, 0, 0}}, {"max", {1, 1, 1}}})}),
         "sim.sources[0].temperature", "found nothing"},
        {"sources", json::array({json::object({{"type", "jet"}, {"min", {0, 0, 0}}, {"max", {1, 1, 1}},
                                                {"velocity", {0, 1, 0}}, {"concentration", 1.5}})}),
         "sim.sources[0].concentration", "a number in [0, 1]"},
        {"ambient_temperature", 0, "sim.ambient_temperature", "a number > 0"},
        {"optics", json::object({{"mixing", "average"}}), "sim.optics.mixing", "one of"},
        {"optics", json::object({{"dye_extinction", 1}, {"dye_scattering", 2}}), "sim.optics.dye_scattering",
         "dye_scattering <= dye_extinction"},
        {"optics", json::object({{"index_a", -1.3}}), "sim.optics.index_a", "a number in [0.001, 1000]"},
        {"heater", 5, "sim.heater", "one of the keys"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.path);
        expectErrorAt(sceneWithSim(json::object({{c.key, c.value}})), c.path, c.detail);
    }
    expectErrorAt(sceneWithSim(json::object({{"substeps", 20}, {"max_substeps", 10}})), "sim.max_substeps",
                  "expected at least sim.substeps (20), found 10");
}

}  // namespace
}  // namespace eikon
