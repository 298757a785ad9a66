// Caustic polygons (render/stages/CausticPolygons.h) in the image-space
// caustic maps, against a closed form the renderer's code does not share.
#include "io/scene/SceneParser.h"
#include "render/graph/FrameRenderer.h"
#include "sim/SceneFields.h"
#include "sim/voxelize/AnalyticVoxelizer.h"
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"

#include <gtest/gtest.h>

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

namespace eikon {
namespace {

// Sunlight straight down through a clear glass slab, |x|, |z| ≤ 0.3 m, onto
// unfiltered receivers on the floor, `receivers` (a JSON list).
Scene slabScene(const std::string& name, const std::string& receivers) {
    const std::string path = ::testing::TempDir() + name + ".json";
    std::ofstream(path) << R"({
      "grid": {"resolution": [16, 16, 16], "bounds": {"min": [-0.5, 0.0, -0.5], "max": [0.5, 1.0, 0.5]}},
      "objects": [{"type": "box", "min": [-0.3, 0.3, -0.3], "max": [0.3, 0.4, 0.3], "index": 1.5}],
      "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": 1.0}],
      "receivers": )" + receivers + R"(,
      "camera": {"position": [0.0, 2.0, 1.5], "target": [0.0, 0.0, 0.0], "up": [0, 1, 0], "fov_deg": 40},
      "render": {"method": "image_space", "width": 64, "height": 48, "caustic_map_texels": 48}
    })";
    return loadSceneFile(path);
}

// The worst relative error of the floor's texels under the slab (against
// E·(1 − R)²) and beside it (against E), away from its edges, over all receivers.
struct SlabFigures {
    double worstUnder = 0.0, worstBeside = 0.0;
    int under = 0, beside = 0;
};

// The centre of texel (i, j) of a receiver's map.
glm::vec3 texelCentre(const layout::GpuReceiver& receiver, int i, int j) {
    const auto n = static_cast<float>(receiver.map.y);
    return glm::vec3(receiver.origin) + ((i + 0.5f) / n - 0.5f) * receiver.origin.w * glm::vec3(receiver.axisU) +
           ((j + 0.5f) / n - 0.5f) * receiver.origin.w * glm::vec3(receiver.axisV);
}

SlabFigures slabFigures(const Scene& scene) {
    const FieldSet fields = sim::voxelizeScene(scene);
    render::FrameRenderer renderer(scene, fields);
    renderer.render(fields);
    const double reflectance = std::pow(0.5 / 2.5, 2.0), transmitted = std::pow(1.0 - reflectance, 2.0);
    SlabFigures figures;
    for (unsigned r = 0; r < renderer.receivers().count(); ++r) {
        const layout::GpuReceiver& receiver = renderer.receivers().receiver(r);
        const std::vector<float> rgb = renderer.receivers().download(r);
        const auto n = static_cast<int>(receiver.map.y);
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const glm::vec3 x = texelCentre(receiver, i, j);
                const double irradiance = rgb[3 * (static_cast<std::size_t>(j) * n + i) + 1];
                const double off = std::max(std::abs(x.x), std::abs(x.z));
                if (off < 0.27) {
                    figures.worstUnder = std::max(figures.worstUnder, std::abs(irradiance / transmitted - 1.0));
                    ++figures.under;
                } else if (off > 0.33) {
                    figures.worstBeside = std::max(figures.worstBeside, std::abs(irradiance - 1.0));
                    ++figures.beside;
                }
            }
    }
    return figures;
}

// Every ray crosses both faces at normal incidence, so under the slab the
// floor receives E·(1 − R)², R = ((n − 1)/(n + 1))² (the partial
// reflections inside are not followed), and E beside it: both to 0.5% in
// every texel of `receivers` (over `minimumBeside` texels beside the slab),
// reported as `figure`_worst_relative_error_under and _beside.
void expectFlatFloor(const std::string& figure, const std::string& receivers, int minimumBeside) {
    const SlabFigures figures = slabFigures(slabScene(figure, receivers));
    test::reportFigure((figure + "_worst_relative_error_under").c_str(), figures.worstUnder);
    test::reportFigure((figure + "_worst_relative_error_beside").c_str(), figures.worstBeside);
    EXPECT_GT(figures.under, 1000);
    EXPECT_GT(figures.beside, minimumBeside);
    EXPECT_LE(figures.worstUnder, 0.005);
    EXPECT_LE(figures.worstBeside, 0.005);
}

// With fewer photons than floor texels, caustic polygons spread each cell's
// power over the area it lands on, so the field is flat; photons splatted
// at points would show their grid against the floor's as moiré, several
// percent from texel to texel (render/stages/CausticPolygons.h).
TEST(CausticPolygons, CarryAUniformBeamThroughASlabUniformly) {
    test::glContext();
    expectFlatFloor(
        "image_space_slab",
        R"([{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "size": 1.0, "resolution": 64, "filter": "none"}])",
        1000);
}

// On finer floors the cells span more texels: at 160² they are drawn by the
// raster pipeline or deposited by compute by their size, side by side, and
// the two must sample the same texel centres and cover each once across
// the edges the paths share; at 256² nearly every cell is drawn.
TEST(CausticPolygons, CarryAUniformBeamUniformlyWhetherItsCellsAreDrawnOrDeposited) {
    test::glContext();
    for (const int resolution : {160, 256}) {
        const std::string name = "image_space_slab_" + std::to_string(resolution);
        expectFlatFloor(name,
                        R"([{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "size": 1.0, "resolution": )" +
                            std::to_string(resolution) + R"(, "filter": "none"}])",
                        1000);
    }
}

// The same floor as two receivers of different resolutions side by side,
// the slab across their seam and past their far edges: each cell is drawn
// on every receiver its photons land on, clipped to each square, into each
// receiver's own rows of the atlas.
TEST(CausticPolygons, KeepEachReceiverToItsOwnMapInTheAtlas) {
    test::glContext();
    expectFlatFloor(
        "image_space_two_receivers",
        R"([{"type": "plane", "point": [-0.25, 0, 0], "normal": [0, 1, 0], "size": 0.5, "resolution": 32, "filter": "none"},
            {"type": "plane", "point": [0.25, 0, 0], "normal": [0, 1, 0], "size": 0.5, "resolution": 48, "filter": "none"}])",
        300);
}

// Where a cell is too small to draw it is splatted whole at its middle,
// drawn as a point that shares its power bilinearly among the four texels
// around it (shaders/caustic_splats.*), the shares of texels off its
// receiver's square given to those on it. On floors of 4² and 7² texels
// side by side under the slab every cell is splatted. The light's photons
// sit on a grid of spacing h over the slab's bounding sphere (radius 1.01 ×
// half the box's diagonal, 48 texels across), straight through to the
// floor, so a cell's middle lies on a whole multiple of h; the squares'
// edges lie halfway between, where a cell's power is either all on a
// square or all off it. Every texel, those at the squares' edges and along
// their seam included, then gets E·(1 − R)², the power landing on it: none
// leaks off a square or into the other receiver's rows of the atlas.
TEST(CausticPolygons, SplatCellsTooSmallToDrawWithoutLosingPower) {
    test::glContext();
    const double h = 2.0 * 1.01 * 0.5 * std::sqrt(0.6 * 0.6 + 0.1 * 0.1 + 0.6 * 0.6) / 48.0;
    const double edge = 14.0 * h;  // x from −14.5 h to −0.5 h and on to 13.5 h; z from −7.5 h to 6.5 h
    const auto plane = [&](double x, int texels) {
        return R"({"type": "plane", "point": [)" + std::to_string(x) + ", 0, " + std::to_string(-0.5 * h) +
               R"(], "normal": [0, 1, 0], "size": )" + std::to_string(edge) +
               R"(, "resolution": )" + std::to_string(texels) + R"(, "filter": "none"})";
    };
    const SlabFigures figures =
        slabFigures(slabScene("image_space_splats", "[" + plane(-7.5 * h, 4) + ", " + plane(6.5 * h, 7) + "]"));
    test::reportFigure("image_space_splats_worst_relative_error", figures.worstUnder);
    EXPECT_EQ(figures.under, 4 * 4 + 7 * 7);
    EXPECT_LE(figures.worstUnder, 0.005);
}

// Sunlight straight down through a glass bar (n = 1.5, |x|, |z| ≤ 0.2 m,
// flat top at y = 0.5) whose underside is a V-notch: two facets rising at
// α = 30° from its bottom edges (y = 0.3) to a ridge along z at x = 0. Each
// facet bends its light away from the ridge, by δ = asin(n sin α) − α, so
// under the ridge the floor gets no light between the two beams' inner
// edges, x = ±y_ridge·tan δ. The facets meet at 60°, a crease
// (bridge/mesh/Creases.h): the cells of photons that left on either side of
// the ridge must not be drawn across the gap. Each beam is uniform: E·T_top
// ·T_exit over its compression 1 − tan α·tan δ along x (T by Fresnel,
// unpolarized). Both to 1% of E on a 64² floor.
TEST(CausticPolygons, KeepTheGapUnderACreaseDark) {
    test::glContext();
    const double n = 1.5, alpha = 30.0 * std::numbers::pi / 180.0;
    const double ridge = 0.3 + 0.2 * std::tan(alpha);
    // The cross-section, counter-clockwise from +z, at z = +0.2 (0–4) and −0.2 (5–9).
    const double section[5][2] = {{-0.2, 0.3}, {0.0, ridge}, {0.2, 0.3}, {0.2, 0.5}, {-0.2, 0.5}};
    TriangleMesh bar;
    for (const double z : {0.2, -0.2})
        for (const auto& p : section) bar.vertices.emplace_back(p[0], p[1], z);
    bar.triangles = {{4, 0, 1}, {4, 1, 3}, {1, 2, 3}, {9, 6, 5}, {9, 8, 6}, {6, 8, 7}};  // the caps
    for (int i = 0; i < 5; ++i) {  // the sides, edge i → i + 1
        const int a = i, b = (i + 1) % 5;
        bar.triangles.emplace_back(a + 5, b + 5, b);
        bar.triangles.emplace_back(a + 5, b, a);
    }
    const std::string obj = test::meshObject(bar, "notched_bar.obj", n).mesh.path;
    const std::string path = ::testing::TempDir() + "notched_bar.json";
    std::ofstream(path) << R"({
      "grid": {"resolution": [16, 16, 16], "bounds": {"min": [-0.5, 0.0, -0.5], "max": [0.5, 1.0, 0.5]}},
      "objects": [{"type": "mesh", "mesh": {"path": ")" + obj + R"("}, "index": 1.5}],
      "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": 1.0}],
      "receivers": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "size": 1.0, "resolution": 64, "filter": "none"}],
      "camera": {"position": [0.0, 2.0, 1.5], "target": [0.0, 0.0, 0.0], "up": [0, 1, 0], "fov_deg": 40},
      "render": {"method": "image_space", "width": 64, "height": 48, "caustic_map_texels": 48}
    })";
    const Scene scene = loadSceneFile(path);
    const sim::SceneFields fields(scene);
    render::FrameRenderer renderer(scene, fields.fields());
    renderer.render(fields.fields());

    const auto reflectance = [](double cosI, double cosT, double n1, double n2) {
        const double s = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT), p = (n2 * cosI - n1 * cosT) / (n2 * cosI + n1 * cosT);
        return 0.5 * (s * s + p * p);
    };
    const double exitAngle = std::asin(n * std::sin(alpha)), delta = exitAngle - alpha;
    const double beam = (1.0 - reflectance(1.0, 1.0, 1.0, n)) *
                        (1.0 - reflectance(std::cos(alpha), std::cos(exitAngle), n, 1.0)) /
                        (1.0 - std::tan(alpha) * std::tan(delta));
    const double gapEdge = ridge * std::tan(delta);  // 0.14 m
    const layout::GpuReceiver& floor = renderer.receivers().receiver(0);
    const std::vector<float> rgb = renderer.receivers().download(0);
    double brightestInGap = 0.0, worstInBeam = 0.0;
    int inGap = 0, inBeam = 0;
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i) {
            const glm::vec3 centre = texelCentre(floor, i, j);
            const double x = centre.x, z = centre.z;
            if (std::abs(z) > 0.17) continue;
            const double irradiance = rgb[3 * (static_cast<std::size_t>(j) * 64 + i) + 1];
            if (std::abs(x) < gapEdge - 0.03) {
                brightestInGap = std::max(brightestInGap, irradiance);
                ++inGap;
            } else if (std::abs(x) > gapEdge + 0.01 && std::abs(x) < 0.19) {
                worstInBeam = std::max(worstInBeam, std::abs(irradiance / beam - 1.0));
                ++inBeam;
            }
        }
    test::reportFigure("image_space_crease_gap_brightest", brightestInGap);
    test::reportFigure("image_space_crease_beam_worst_relative_error", worstInBeam);
    EXPECT_GT(inGap, 200);
    EXPECT_GT(inBeam, 60);
    EXPECT_LE(brightestInGap, 0.01);
    EXPECT_LE(worstInBeam, 0.01);
}

}  // namespace
}  // namespace eikon
