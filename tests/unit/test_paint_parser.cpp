// The `paint` list: valid strokes parse with their defaults, bad ones name
// their JSON path.
#include "io/scene/SceneParser.h"
#include "tests/unit/SceneParserTestSupport.h"

#include <gtest/gtest.h>

namespace eikon {
namespace {

using test::expectErrorAt;
using test::json;

json withPaint(json stroke) {
    json scene = test::validScene();
    scene["paint"] = json::array({std::move(stroke)});
    return scene;
}

TEST(PaintParser, ReadsAStrokeAndItsDefaults) {
    const Scene scene = parseScene(withPaint(json::parse(R"({"brush": "smoke", "where": "outside_objects",
        "path": [[0, 0.1, 0], [0.2, 0.1, 0]], "radius": 0.05, "extinction": [3, 2, 1], "scattering": 1, "seed": 9})")),
                                   "scene.json");
    ASSERT_EQ(scene.paint.size(), 1u);
    const PaintStroke& stroke = scene.paint[0];
    EXPECT_EQ(stroke.brush, PaintStroke::Brush::Smoke);
    EXPECT_EQ(stroke.where, PaintStroke::Where::OutsideObjects);
    EXPECT_EQ(stroke.path.size(), 2u);
    EXPECT_EQ(stroke.extinction, Rgb(3, 2, 1));
    EXPECT_EQ(stroke.scattering, Rgb(1.0));
    EXPECT_EQ(stroke.index, 0.0);
    EXPECT_EQ(stroke.seed, 9u);

    const Scene plain = parseScene(withPaint(json::parse(R"({"path": [[0, 0, 0]], "radius": 0.1, "index": 0.01})")),
                                   "scene.json");
    EXPECT_EQ(plain.paint[0].brush, PaintStroke::Brush::Soft);
    EXPECT_EQ(plain.paint[0].where, PaintStroke::Where::Everywhere);
}

TEST(PaintParser, BadStrokesNameTheirPath) {
    expectErrorAt(withPaint(json::parse(R"({"path": [], "radius": 0.1, "index": 0.01})")), "paint[0].path",
                  "at least one point");
    expectErrorAt(withPaint(json::parse(R"({"path": [[0, 0, 0]], "radius": 0, "index": 0.01})")), "paint[0].radius");
    expectErrorAt(withPaint(json::parse(R"({"path": [[0, 0, 0]], "radius": 0.1, "brush": "spray", "index": 1})")),
                  "paint[0].brush", "\"soft\"");
    expectErrorAt(withPaint(json::parse(R"({"path": [[0, 0, 0]], "radius": 0.1, "extinction": 1, "scattering": 2})")),
                  "paint[0].scattering", "scattering <=");
    expectErrorAt(withPaint(json::parse(R"({"path": [[0, 0, 0]], "radius": 0.1})")), "paint[0]", "paints something");
    expectErrorAt(withPaint(json::parse(R"({"path": [[0, 0, 0]], "radius": 0.1, "index": 1, "size": 2})")),
                  "paint[0].size");
}

}  // namespace
}  // namespace eikon
