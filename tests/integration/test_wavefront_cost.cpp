// The wavefront's start, counted before it runs (WavefrontStage.h,
// wavefrontStartPatches), against what the pass reports it seeded: every
// emitter face's grid_cells² cells of two patches, in the main wavefront and
// each reflected branch, per channel where the medium disperses.
#include "io/scene/SceneParser.h"
#include "render/graph/FrameRenderer.h"
#include "render/stages/WavefrontStage.h"
#include "sim/SceneFields.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <string>

namespace eikon {
namespace {

nlohmann::json sphereScene() {
    return nlohmann::json::parse(R"({
      "grid": {"resolution": [16, 16, 16], "bounds": {"min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5]}},
      "objects": [{"type": "sphere", "center": [0, 0.5, 0], "radius": 0.2, "index": 1.5}],
      "lights": [{"type": "point", "position": [0, 1.5, 0], "power": [10, 10, 10]}],
      "receivers": [{"type": "plane", "point": [0, 0.05, 0], "normal": [0, 1, 0], "size": 1.0, "resolution": 32}],
      "camera": {"position": [0, 1, 2], "target": [0, 0.3, 0], "up": [0, 1, 0], "fov_deg": 45},
      "render": {"photons": 4096, "width": 16, "height": 12, "seed": 3, "error_estimate": false},
      "tracer": {"estimator": "wavefront", "wavefront": {"grid_cells": 8}}
    })");
}

// Counted from the scene, and as the pass seeded them.
void expectStart(const std::string& label, const nlohmann::json& document, std::uint64_t expected) {
    test::glContext();
    const Scene scene = parseScene(document, "cost.json");
    EXPECT_EQ(render::wavefrontStartPatches(scene), expected) << label;
    const sim::SceneFields fields(scene);
    render::FrameRenderer renderer(scene, fields.fields());
    EXPECT_EQ(renderer.render(fields.fields()).photons.wavefront.startPatches, expected) << label;
}

TEST(WavefrontCost, TheStartCountsEveryFaceChannelAndBranch) {
    const nlohmann::json sphere = sphereScene();
    // A point light's cone toward the sphere and floor is narrower than 60°:
    // one face; the glass sphere adds the reflected branch.
    expectStart("one face, one branch", sphere, 8 * 8 * 2 * 2);
    nlohmann::json branches = sphere;
    branches["tracer"]["wavefront"]["reflections"] = 3;
    expectStart("three branches", branches, 8 * 8 * 2 * 4);
    nlohmann::json dispersive = sphere;
    dispersive["tracer"]["dispersion"] = {1.0, 1.01, 1.02};
    expectStart("dispersive", dispersive, 8 * 8 * 2 * 2 * 3);
    // A light inside the region it lights: the six faces of its cube.
    nlohmann::json inside = sphere;
    inside["lights"][0]["position"] = {0.3, 0.5, 0.3};
    expectStart("six faces", inside, 6 * 8 * 8 * 2 * 2);
    nlohmann::json bare = sphere;
    bare["objects"] = nlohmann::json::array();
    expectStart("no sharp surface", bare, 8 * 8 * 2);
}

}  // namespace
}  // namespace eikon
