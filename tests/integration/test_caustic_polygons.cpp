// Caustic polygons (render/stages/CausticPolygons.h) in the image-space
// caustic maps, against a closed form the renderer's code does not share.
#include "io/scene/SceneParser.h"
#include "render/graph/FrameRenderer.h"
#include "sim/voxelize/AnalyticVoxelizer.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

namespace eikon {
namespace {

// Sunlight straight down through a clear glass slab onto an unfiltered
// floor, with fewer photons than floor texels: every ray crosses both faces
// at normal incidence, so under the slab the floor receives E·(1 − R)²,
// R = ((n − 1)/(n + 1))² (the partial reflections inside are not followed),
// and E beside it. Caustic polygons spread each cell's power over the area
// it lands on, so the field is flat; photons splatted at points would show
// their grid against the floor's as moiré, several percent from texel to
// texel (render/stages/CausticPolygons.h). Bounded at 0.5% per texel.
TEST(CausticPolygons, CarryAUniformBeamThroughASlabUniformly) {
    test::glContext();
    const std::string path = ::testing::TempDir() + "image_space_slab.json";
    std::ofstream(path) << R"({
      "grid": {"resolution": [16, 16, 16], "bounds": {"min": [-0.5, 0.0, -0.5], "max": [0.5, 1.0, 0.5]}},
      "objects": [{"type": "box", "min": [-0.3, 0.3, -0.3], "max": [0.3, 0.4, 0.3], "index": 1.5}],
      "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": 1.0}],
      "receivers": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "size": 1.0, "resolution": 64,
                     "filter": "none"}],
      "camera": {"position": [0.0, 2.0, 1.5], "target": [0.0, 0.0, 0.0], "up": [0, 1, 0], "fov_deg": 40},
      "render": {"method": "image_space", "width": 64, "height": 48, "caustic_map_texels": 48}
    })";
    const Scene scene = loadSceneFile(path);
    const FieldSet fields = sim::voxelizeScene(scene);
    render::FrameRenderer renderer(scene, fields);
    renderer.render(fields);
    const std::vector<float> rgb = renderer.receivers().download(0);
    const double reflectance = std::pow(0.5 / 2.5, 2.0), under = std::pow(1.0 - reflectance, 2.0);
    const int n = scene.receivers[0].resolution;
    double worstUnder = 0.0, worstBeside = 0.0;
    int underTexels = 0, besideTexels = 0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const double u = (i + 0.5) / n - 0.5, v = (j + 0.5) / n - 0.5;
            const double irradiance = rgb[3 * (static_cast<std::size_t>(j) * n + i) + 1];
            if (std::max(std::abs(u), std::abs(v)) < 0.27) {
                worstUnder = std::max(worstUnder, std::abs(irradiance / under - 1.0));
                ++underTexels;
            } else if (std::max(std::abs(u), std::abs(v)) > 0.33) {
                worstBeside = std::max(worstBeside, std::abs(irradiance - 1.0));
                ++besideTexels;
            }
        }
    test::reportFigure("image_space_slab_worst_relative_error_under", worstUnder);
    test::reportFigure("image_space_slab_worst_relative_error_beside", worstBeside);
    EXPECT_GT(underTexels, 1000);
    EXPECT_GT(besideTexels, 1000);
    EXPECT_LE(worstUnder, 0.005);
    EXPECT_LE(worstBeside, 0.005);
}

}  // namespace
}  // namespace eikon
