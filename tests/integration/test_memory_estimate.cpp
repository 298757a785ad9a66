// render/graph/MemoryEstimate against what the renderer's GL objects take
// (gl/GpuMemory's reservations). Each documented size is doubled on a
// scene and the estimate's growth compared with the growth of the bytes
// the renderer holds (what does not scale with it, such as the photons a
// CPU driver suspends at its loop cap, cancels): never more, so that the
// estimate refuses no scene that fits, and at least half, so that it
// refuses one far past the limit.
#include "gl/GpuMemory.h"
#include "io/image/ImageIo.h"
#include "io/scene/SceneParser.h"
#include "render/graph/FrameRenderer.h"
#include "render/graph/MemoryEstimate.h"
#include "sim/SceneFields.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace eikon {
namespace {

namespace fs = std::filesystem;

nlohmann::json sphereScene() {
    return nlohmann::json::parse(R"({
      "grid": {"resolution": [24, 20, 16], "bounds": {"min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5]}},
      "objects": [{"type": "sphere", "center": [0, 0.5, 0], "radius": 0.2, "index": 1.5}],
      "lights": [{"type": "point", "position": [0, 1.5, 0], "power": [10, 10, 10]}],
      "receivers": [{"type": "plane", "point": [0, 0.05, 0], "normal": [0, 1, 0], "size": 1.0, "resolution": 48}],
      "camera": {"position": [0, 1, 2], "target": [0, 0.3, 0], "up": [0, 1, 0], "fov_deg": 45},
      "render": {"photons": 4096, "width": 32, "height": 24, "seed": 3, "device": "gpu"}
    })");
}
// On "gpu" the grid passes hold their scratch and the octree's pyramid in GL
// memory, as the estimate counts them; the native loops (render.device
// "cpu", or "auto" under a software rasterizer) hold the same bytes on the
// host instead, which the estimate's total covers but its split does not.

struct Footprint {
    std::uint64_t estimated = 0, held = 0;  // GL bytes
};

// The estimate's GL bytes and what the renderer holds after a frame, as
// `eikon run` makes it (errors estimated where the scene asks).
Footprint footprint(const nlohmann::json& document) {
    test::glContext();
    const Scene scene = parseScene(document, (fs::path(::testing::TempDir()) / "estimate.json").string());
    Footprint result;
    for (const render::MemoryItem& item : render::estimateMemory(scene)) result.estimated += item.glBytes;
    const sim::SceneFields fields(scene);
    const std::uint64_t before = gl::gpuBytesHeld();
    render::RendererOptions options;
    options.estimateErrors = scene.render.errorEstimate;
    render::FrameRenderer renderer(scene, fields.fields(), options);
    renderer.render(fields.fields());
    result.held = gl::gpuBytesHeld() - before;
    return result;
}

void expectGrowthFloor(const std::string& label, nlohmann::json document,
                       const std::function<void(nlohmann::json&)>& doubleIt) {
    const Footprint small = footprint(document);
    doubleIt(document);
    const Footprint large = footprint(document);
    const std::uint64_t estimated = large.estimated - small.estimated, held = large.held - small.held;
    EXPECT_GT(estimated, 0u) << label;
    EXPECT_LE(estimated, held) << label;
    EXPECT_GE(estimated, held / 2) << label << ": " << estimated << " of " << held;
    test::reportFigure(("estimated_share_" + label).c_str(), double(estimated) / double(held));
}

void doubleGrid(nlohmann::json& scene) { scene["grid"]["resolution"] = {48, 40, 32}; }

void doubleImage(nlohmann::json& scene) {
    scene["render"]["width"] = 64;
    scene["render"]["height"] = 48;
}

TEST(MemoryEstimate, GrowsWithEachSizeAsTheRendererDoesAndNoMore) {
    const nlohmann::json photons = sphereScene();
    expectGrowthFloor("grid", photons, doubleGrid);
    expectGrowthFloor("receiver", photons, [](nlohmann::json& s) { s["receivers"][0]["resolution"] = 96; });
    expectGrowthFloor("image", photons, doubleImage);

    nlohmann::json uniform = sphereScene();
    uniform["tracer"] = {{"step_policy", "uniform"}};
    expectGrowthFloor("grid_uniform_steps", uniform, doubleGrid);

    nlohmann::json milk = sphereScene();
    milk["medium"] = {{"extinction", {4, 4, 4}}, {"scattering", {3, 3, 3}}};
    milk["tracer"] = {{"multiple_scattering", "lbm"}, {"lbm_max_iterations", 16}};
    expectGrowthFloor("grid_lattice", milk, doubleGrid);

    nlohmann::json wavefront = sphereScene();
    wavefront["tracer"] = {{"estimator", "wavefront"}, {"wavefront", {{"grid_cells", 16}, {"max_patches", 32768}}}};
    expectGrowthFloor("wavefront_patches", wavefront,
                      [](nlohmann::json& s) { s["tracer"]["wavefront"]["max_patches"] = 65536; });

    nlohmann::json imageSpace = sphereScene();
    imageSpace["render"]["method"] = "image_space";
    imageSpace["render"]["caustic_map_texels"] = 64;
    expectGrowthFloor("caustic_maps", imageSpace, [](nlohmann::json& s) { s["render"]["caustic_map_texels"] = 128; });
    expectGrowthFloor("image_space_image", imageSpace, doubleImage);

    const fs::path folder = fs::path(::testing::TempDir());
    io::writeHdr(folder / "estimate_sky_small.hdr", 128, 64, std::vector<float>(128 * 64 * 4, 1.0f));
    io::writeHdr(folder / "estimate_sky_large.hdr", 256, 128, std::vector<float>(256 * 128 * 4, 1.0f));
    nlohmann::json environment = sphereScene();
    environment["render"]["environment"] = {{"type", "hdr"}, {"path", (folder / "estimate_sky_small.hdr").string()}};
    expectGrowthFloor("environment", environment, [&](nlohmann::json& s) {
        s["render"]["environment"]["path"] = (folder / "estimate_sky_large.hdr").string();
    });
}

}  // namespace
}  // namespace eikon
