// render.method, render.method_fallback and render.caustic_map_texels: image
// space is refused, at render.method, for a scene with media it cannot show
// (bridge/scene/ImageSpaceScope.h), unless the fallback allows drawing the
// surfaces only.
#include "bridge/scene/ImageSpaceScope.h"
#include "io/scene/SceneParser.h"
#include "tests/unit/SceneParserTestSupport.h"

#include <gtest/gtest.h>

namespace eikon {
namespace {

using test::expectErrorAt;
using test::json;
using test::validScene;

// The valid scene less what image space cannot show: the medium's fog and the box's scattering.
json surfacesOnlyScene() {
    json scene = validScene();
    scene["medium"] = {{"index", 1.0}};
    scene["objects"][1].erase("scattering");
    return scene;
}

TEST(SceneParserRenderMethod, DefaultsToTheEikonalMethod) {
    const RenderDesc render = parseScene(validScene(), "test.json").render;
    EXPECT_EQ(render.method, RenderDesc::Method::Eikonal);
    EXPECT_EQ(render.methodFallback, RenderDesc::MethodFallback::None);
    EXPECT_EQ(render.causticMapTexels, 256);
}

TEST(SceneParserRenderMethod, ImageSpaceTakesASceneOfSurfaces) {
    json scene = surfacesOnlyScene();
    scene["render"]["method"] = "image_space";
    scene["render"]["caustic_map_texels"] = 512;
    const Scene parsed = parseScene(scene, "test.json");
    EXPECT_EQ(parsed.render.method, RenderDesc::Method::ImageSpace);
    EXPECT_EQ(parsed.render.causticMapTexels, 512);
    EXPECT_TRUE(imageSpaceOmissions(parsed).empty());
    EXPECT_EQ(describeImageSpaceOmissions(parsed), "");
}

TEST(SceneParserRenderMethod, ImageSpaceRefusesMediaItWouldDrop) {
    json scene = validScene();  // fog in the medium, scattering in the box
    scene["render"]["method"] = "image_space";
    expectErrorAt(scene, "render.method", "the medium's extinction and scattering and objects[1]'s scattering");
    json mirage = surfacesOnlyScene();
    mirage["render"]["method"] = "image_space";
    mirage["medium"]["air_temperature_profile"] = {
        {"ground_temperature", 330.0}, {"air_temperature", 300.0}, {"scale_height", 0.05}};
    expectErrorAt(mirage, "render.method", "air_temperature_profile");
    json smooth = surfacesOnlyScene();
    smooth["render"]["method"] = "image_space";
    smooth["objects"][0]["surface"] = "smooth";
    expectErrorAt(smooth, "render.method", "objects[0] (a smooth surface is a graded field)");
}

TEST(SceneParserRenderMethod, TheFallbackDrawsTheSurfacesAndNamesWhatItDrops) {
    json scene = validScene();
    scene["render"]["method"] = "image_space";
    scene["render"]["method_fallback"] = "surfaces_only";
    const Scene parsed = parseScene(scene, "test.json");
    EXPECT_EQ(parsed.render.methodFallback, RenderDesc::MethodFallback::SurfacesOnly);
    EXPECT_EQ(imageSpaceOmissions(parsed).size(), 2u);
    EXPECT_NE(describeImageSpaceOmissions(parsed).find("drops the medium's extinction and scattering"),
              std::string::npos);
}

TEST(SceneParserRenderMethod, BadValuesAreRefusedAtTheirPath) {
    for (const auto& [key, value, detail] :
         {std::tuple<const char*, json, const char*>{"method", "raster", "\"image_space\""},
          {"method_fallback", "all", "\"surfaces_only\""},
          {"caustic_map_texels", 8, "16"},
          {"caustic_map_texels", 5000, "4096"}}) {
        json scene = surfacesOnlyScene();
        scene["render"][key] = value;
        expectErrorAt(scene, std::string("render.") + key, detail);
    }
}

}  // namespace
}  // namespace eikon
