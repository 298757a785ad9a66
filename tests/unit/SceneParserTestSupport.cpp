#include "tests/unit/SceneParserTestSupport.h"

#include "bridge/core/Error.h"
#include "io/scene/SceneParser.h"

#include <gtest/gtest.h>

#include <fstream>

namespace eikon::test {

const char* const kValidScene = R"({
  "description": "a glass sphere and a box above a floor",
  "grid": {"resolution": [32, 16, 8], "bounds": {"min": [-1, -0.5, -2], "max": [1, 0.5, 2]},
           "smoothing_sigma_voxels": 0.75, "supersampling": 2},
  "medium": {"index": 1.0003, "extinction": 0.01, "scattering": [0.001, 0.002, 0.003]},
  "objects": [
    {"type": "sphere", "center": [0, 0.1, 0], "radius": 0.4, "index": 1.5, "extinction": [0.1, 0.2, 0.3]},
    {"type": "box", "min": [-0.5, -0.5, -0.5], "max": [0.5, 0, 0.5], "index": 1.33,
     "extinction": 2, "scattering": 1}
  ],
  "lights": [
    {"type": "point", "position": [0, 2, 0], "power": [10, 20, 30]},
    {"type": "directional", "direction": [0, -3, 0], "irradiance": 500}
  ],
  "receivers": [
    {"type": "plane", "point": [0, -0.5, 0], "normal": [0, 2, 0]},
    {"type": "plane", "point": [0, 0, -2], "normal": [0, 0, 1], "albedo": [0.2, 0.5, 1], "size": 4,
     "resolution": 512}
  ],
  "camera": {"position": [0, 1, 4], "target": [0, 0, 0], "up": [0, 1, 0], "fov_deg": 35},
  "render": {"photons": 1e6, "width": 320, "height": 240, "seed": 7, "exposure_ev": -1.5,
             "step_voxels": 0.25, "background": 0.1}
})";


json validScene() { return json::parse(kValidScene); }

std::string writeTempFile(const std::string& name, const std::string& contents) {
    const std::string path = ::testing::TempDir() + name;
    std::ofstream(path) << contents;
    return path;
}

std::string parseErrorMessage(const json& root) {
    try {
        parseScene(root, "test.json");
    } catch (const InputError& error) {
        return error.what();
    }
    ADD_FAILURE() << "parseScene accepted " << root.dump();
    return "";
}

void expectErrorAt(const json& root, const std::string& path, const std::string& detail) {
    const std::string message = parseErrorMessage(root);
    EXPECT_NE(message.find("test.json: " + path + ": expected"), std::string::npos) << message;
    EXPECT_NE(message.find(detail), std::string::npos) << message;
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

}  // namespace eikon::test
