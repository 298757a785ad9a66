// camera.projection and the `diagnostic` section: defaults, each type's and
// cut-off's own keys, and every refusal at its key path — a perspective
// camera, image space, sharp objects, values out of range, keys of another
// type — with `--set` reaching the section as any other.
#include "bridge/core/Error.h"
#include "io/image/ImageIo.h"
#include "io/scene/SceneOverride.h"
#include "io/scene/SceneParser.h"
#include "tests/unit/SceneParserTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace eikon {
namespace {

using test::expectErrorAt;
using test::json;
using test::validScene;

// The valid scene with smooth objects, an orthographic camera and `diagnostic`.
json diagnosticScene(const json& diagnostic) {
    json scene = validScene();
    scene["objects"][0]["surface"] = "smooth";
    scene["objects"][1]["surface"] = "smooth";
    scene["camera"] = {{"position", {0, 0, 4}}, {"target", {0, 0, 0}}, {"projection", "orthographic"}, {"width_m", 2.0}};
    scene["diagnostic"] = diagnostic;
    return scene;
}

TEST(SceneParserCamera, IsAPerspectiveCameraUnlessToldOtherwise) {
    const CameraDesc camera = parseScene(validScene(), "test.json").camera;
    EXPECT_EQ(camera.projection, CameraDesc::Projection::Perspective);
    EXPECT_FALSE(camera.orthographic());
}

TEST(SceneParserCamera, AnOrthographicCameraTakesItsWidthAndKeepsFovDegUnused) {
    json scene = validScene();
    scene["camera"]["projection"] = "orthographic";
    scene["camera"]["width_m"] = 0.75;
    const CameraDesc camera = parseScene(scene, "test.json").camera;
    EXPECT_TRUE(camera.orthographic());
    EXPECT_DOUBLE_EQ(camera.widthM, 0.75);
}

TEST(SceneParserCamera, RefusesAMissingOrMisplacedWidthAndImageSpace) {
    json scene = validScene();
    scene["camera"]["projection"] = "orthographic";
    expectErrorAt(scene, "camera.width_m", "found nothing");
    scene["camera"]["width_m"] = 0;
    expectErrorAt(scene, "camera.width_m", "a number in (0, 1000000000]");
    json perspective = validScene();
    perspective["camera"]["width_m"] = 1.0;
    expectErrorAt(perspective, "camera.width_m", "no width_m beside a perspective projection");
    json unknown = validScene();
    unknown["camera"]["projection"] = "fisheye";
    expectErrorAt(unknown, "camera.projection", "one of \"perspective\", \"orthographic\"");
    json imageSpace = validScene();
    imageSpace["medium"] = {{"index", 1.0}};
    imageSpace["objects"][1].erase("scattering");
    imageSpace["render"]["method"] = "image_space";
    imageSpace["camera"]["projection"] = "orthographic";
    imageSpace["camera"]["width_m"] = 1.0;
    expectErrorAt(imageSpace, "camera.projection", "\"perspective\" with render.method \"image_space\"");
}

TEST(SceneParserDiagnostic, HasNoneUnlessGiven) {
    EXPECT_FALSE(parseScene(validScene(), "test.json").diagnostic);
}

TEST(SceneParserDiagnostic, InterferometryDefaultsToAGreenLaserAndNoTilt) {
    const Scene scene = parseScene(diagnosticScene({{"type", "interferometry"}}), "test.json");
    ASSERT_TRUE(scene.diagnostic);
    EXPECT_EQ(scene.diagnostic->type, DiagnosticDesc::Type::Interferometry);
    EXPECT_DOUBLE_EQ(scene.diagnostic->wavelengthNm, 532.0);
    EXPECT_DOUBLE_EQ(scene.diagnostic->fringeTilt, 0.0);
    const Scene tilted = parseScene(
        diagnosticScene({{"type", "interferometry"}, {"wavelength_nm", 632.8}, {"fringe_tilt", -12.5}}), "test.json");
    EXPECT_DOUBLE_EQ(tilted.diagnostic->wavelengthNm, 632.8);
    EXPECT_DOUBLE_EQ(tilted.diagnostic->fringeTilt, -12.5);
}

TEST(SceneParserDiagnostic, SchlierenReadsItsHeadAndCutoff) {
    const Scene defaults = parseScene(diagnosticScene({{"type", "schlieren"}}), "test.json");
    EXPECT_EQ(defaults.diagnostic->type, DiagnosticDesc::Type::Schlieren);
    EXPECT_EQ(defaults.diagnostic->cutoff, DiagnosticDesc::Cutoff::KnifeEdge);
    EXPECT_DOUBLE_EQ(defaults.diagnostic->focalLength, 1.0);
    EXPECT_DOUBLE_EQ(defaults.diagnostic->sourceHeight, 1e-3);
    EXPECT_DOUBLE_EQ(defaults.diagnostic->knifeAngleDeg, 0.0);
    const Scene knife = parseScene(diagnosticScene({{"type", "schlieren"},
                                                    {"focal_length", 2.0},
                                                    {"source_height", 5e-4},
                                                    {"cutoff", "knife_edge"},
                                                    {"knife_angle_deg", 90}}),
                                   "test.json");
    EXPECT_DOUBLE_EQ(knife.diagnostic->focalLength, 2.0);
    EXPECT_DOUBLE_EQ(knife.diagnostic->sourceHeight, 5e-4);
    EXPECT_DOUBLE_EQ(knife.diagnostic->knifeAngleDeg, 90.0);
    for (const auto& [name, cutoff] : {std::pair{"circular", DiagnosticDesc::Cutoff::Circular},
                                       std::pair{"colour", DiagnosticDesc::Cutoff::Colour}})
        EXPECT_EQ(parseScene(diagnosticScene({{"type", "schlieren"}, {"cutoff", name}}), "test.json").diagnostic->cutoff,
                  cutoff);
}

TEST(SceneParserDiagnostic, RefusesBadValuesAndAnotherTypesKeysAtTheirPath) {
    expectErrorAt(diagnosticScene({{"type", "moire"}}), "diagnostic.type",
                  "one of \"interferometry\", \"schlieren\", \"shadowgraph\", \"bos\"");
    expectErrorAt(diagnosticScene(json::object()), "diagnostic.type", "found nothing");
    expectErrorAt(diagnosticScene({{"type", "interferometry"}, {"wavelength_nm", 0}}), "diagnostic.wavelength_nm",
                  "a number in (0, 1000000]");
    expectErrorAt(diagnosticScene({{"type", "interferometry"}, {"focal_length", 1}}), "diagnostic.focal_length",
                  "an unknown key");
    expectErrorAt(diagnosticScene({{"type", "schlieren"}, {"wavelength_nm", 532}}), "diagnostic.wavelength_nm",
                  "an unknown key");
    expectErrorAt(diagnosticScene({{"type", "schlieren"}, {"focal_length", -1}}), "diagnostic.focal_length",
                  "a number in (0, 1000000000]");
    expectErrorAt(diagnosticScene({{"type", "schlieren"}, {"source_height", "1mm"}}), "diagnostic.source_height",
                  "a number in (0, 1000000000]");
    expectErrorAt(diagnosticScene({{"type", "schlieren"}, {"cutoff", "razor"}}), "diagnostic.cutoff",
                  "one of \"knife_edge\", \"circular\", \"colour\"");
    expectErrorAt(diagnosticScene({{"type", "schlieren"}, {"knife_angle_deg", "45"}}), "diagnostic.knife_angle_deg",
                  "a number");
    // render.width 320: fringes two pixels apart at most 160 per width.
    expectErrorAt(diagnosticScene({{"type", "interferometry"}, {"fringe_tilt", 161}}), "diagnostic.fringe_tilt",
                  "a number in [-160, 160]");
}

TEST(SceneParserDiagnostic, ShadowgraphReadsItsScreenDistance) {
    const Scene defaults = parseScene(diagnosticScene({{"type", "shadowgraph"}}), "test.json");
    EXPECT_EQ(defaults.diagnostic->type, DiagnosticDesc::Type::Shadowgraph);
    EXPECT_DOUBLE_EQ(defaults.diagnostic->screenDistance, 1.0);
    EXPECT_DOUBLE_EQ(
        parseScene(diagnosticScene({{"type", "shadowgraph"}, {"screen_distance", 2.5}}), "test.json").diagnostic->screenDistance,
        2.5);
    expectErrorAt(diagnosticScene({{"type", "shadowgraph"}, {"screen_distance", 0}}), "diagnostic.screen_distance",
                  "a number in (0, 1000000000]");
    expectErrorAt(diagnosticScene({{"type", "shadowgraph"}, {"focal_length", 1}}), "diagnostic.focal_length",
                  "an unknown key");
}

// BOS: the valid scene's perspective camera, its objects smooth.
json bosScene(const json& diagnostic) {
    json scene = diagnosticScene(diagnostic);
    scene["camera"] = validScene()["camera"];
    return scene;
}

TEST(SceneParserDiagnostic, BosReadsItsBackgroundAndDots) {
    const Scene defaults = parseScene(bosScene({{"type", "bos"}}), "test.json");
    EXPECT_EQ(defaults.diagnostic->type, DiagnosticDesc::Type::Bos);
    EXPECT_DOUBLE_EQ(defaults.diagnostic->backgroundDistance, 1.0);
    EXPECT_EQ(defaults.diagnostic->seed, 1u);
    EXPECT_FALSE(defaults.diagnostic->dotDiameter);
    EXPECT_DOUBLE_EQ(defaults.diagnostic->dotDensity, 0.3);
    const Scene given = parseScene(bosScene({{"type", "bos"},
                                             {"background_distance", 3.0},
                                             {"pattern", "dots"},
                                             {"seed", 7},
                                             {"dot_diameter", 0.002},
                                             {"dot_density", 0.5}}),
                                   "test.json");
    EXPECT_DOUBLE_EQ(given.diagnostic->backgroundDistance, 3.0);
    EXPECT_EQ(given.diagnostic->seed, 7u);
    EXPECT_DOUBLE_EQ(given.diagnostic->dotDiameter.value(), 0.002);
    EXPECT_DOUBLE_EQ(given.diagnostic->dotDensity, 0.5);
    expectErrorAt(bosScene({{"type", "bos"}, {"pattern", "stripes"}}), "diagnostic.pattern",
                  "\"dots\" or an existing PNG or JPEG image file");
    expectErrorAt(bosScene({{"type", "bos"}, {"pattern_width", 1.0}}), "diagnostic.pattern_width",
                  "no pattern_width with the \"dots\" pattern");
    expectErrorAt(bosScene({{"type", "bos"}, {"seed", -1}}), "diagnostic.seed", "an integer in [0, 4294967295]");
    expectErrorAt(bosScene({{"type", "bos"}, {"seed", 1.5}}), "diagnostic.seed", "an integer");
    expectErrorAt(bosScene({{"type", "bos"}, {"dot_density", 0.6}}), "diagnostic.dot_density", "a number in (0, 0.5]");
    expectErrorAt(bosScene({{"type", "bos"}, {"dot_diameter", -0.001}}), "diagnostic.dot_diameter",
                  "a number in (0, 1000000000]");
    expectErrorAt(bosScene({{"type", "bos"}, {"background_distance", "far"}}), "diagnostic.background_distance",
                  "a number in (0, 1000000000]");
    expectErrorAt(bosScene({{"type", "bos"}, {"screen_distance", 1}}), "diagnostic.screen_distance", "an unknown key");
    expectErrorAt(diagnosticScene({{"type", "bos"}}), "camera.projection",
                  "\"perspective\" with a bos diagnostic");
}

// An image pattern is read with the scene, relative to the scene file's
// folder, its sRGB values decoded to linear light (IEC 61966-2-1); a file
// that is missing or no image stops the parse at the key, naming the file.
TEST(SceneParserDiagnostic, BosReadsAnImagePatternRelativeToTheScene) {
    const std::filesystem::path folder = std::filesystem::path(::testing::TempDir()) / "eikon_bos_pattern";
    std::filesystem::create_directories(folder);
    // 2 × 1 pixels: sRGB 0 and 188 (linear 0.5029), then 255 and a 50% grey alpha.
    io::writePng(folder / "pattern.png", 2, 1, {0, 188, 255, 255, 255, 255, 255, 128});
    const std::string sceneFile = (folder / "scene.json").string();
    const Scene scene = parseScene(bosScene({{"type", "bos"}, {"pattern", "pattern.png"}, {"pattern_width", 0.4}}),
                                   sceneFile);
    const DiagnosticDesc& bos = *scene.diagnostic;
    EXPECT_EQ(bos.patternPath, (folder / "pattern.png").string());
    ASSERT_TRUE(bos.patternImage);
    EXPECT_EQ(bos.patternImage->width, 2);
    EXPECT_EQ(bos.patternImage->height, 1);
    EXPECT_FLOAT_EQ(bos.patternImage->rgba[0], 0.0f);
    EXPECT_NEAR(bos.patternImage->rgba[1], std::pow((188.0 / 255.0 + 0.055) / 1.055, 2.4), 1e-6);
    EXPECT_FLOAT_EQ(bos.patternImage->rgba[4], 1.0f);
    EXPECT_NEAR(bos.patternImage->rgba[7], 128.0 / 255.0, 1e-6);
    EXPECT_DOUBLE_EQ(bos.patternWidth.value(), 0.4);

    std::ofstream(folder / "notes.png") << "not an image";
    try {
        parseScene(bosScene({{"type", "bos"}, {"pattern", "notes.png"}}), sceneFile);
        ADD_FAILURE() << "a file that is no image";
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find("diagnostic.pattern: expected \"dots\" or an existing PNG or JPEG image file"),
                  std::string::npos) << message;
        EXPECT_NE(message.find((folder / "notes.png").string() + "\", which is not one"), std::string::npos) << message;
    }
    expectErrorAt(bosScene({{"type", "bos"}, {"pattern", (folder / "missing.png").string()}}), "diagnostic.pattern",
                  "\"dots\" or an existing PNG or JPEG image file");
    expectErrorAt(bosScene({{"type", "bos"}, {"pattern", (folder / "pattern.png").string()}, {"pattern_width", 0}}),
                  "diagnostic.pattern_width", "a number in (0, 1000000000]");
    std::filesystem::remove_all(folder);
}

TEST(SceneParserDiagnostic, RefusesAPerspectiveCameraAndImageSpace) {
    json perspective = diagnosticScene({{"type", "schlieren"}});
    perspective["camera"] = {{"position", {0, 0, 4}}, {"fov_deg", 30}};
    expectErrorAt(perspective, "camera.projection", "\"orthographic\" with a diagnostic");
    json noCamera = diagnosticScene({{"type", "schlieren"}});
    noCamera.erase("camera");
    expectErrorAt(noCamera, "camera", "a camera with projection \"orthographic\" and width_m");
    json imageSpace = diagnosticScene({{"type", "interferometry"}});
    imageSpace["render"]["method"] = "image_space";
    expectErrorAt(imageSpace, "render.method", "\"eikonal\" with a diagnostic");
}

// The diagnostics' rays cross sharp surfaces as the view's do.
TEST(SceneParserDiagnostic, TakesSharpObjects) {
    json sharp = diagnosticScene({{"type", "interferometry"}});
    sharp["objects"][1].erase("surface");  // sharp by default
    const Scene parsed = parseScene(sharp, "test.json");
    EXPECT_TRUE(parsed.objects[1].isSharp());
    EXPECT_TRUE(parsed.diagnostic.has_value());
}

TEST(SceneParserDiagnostic, SetReachesTheSectionAsAnyOther) {
    json scene = diagnosticScene({{"type", "interferometry"}});
    applyOverride(scene, "diagnostic.type=schlieren");
    applyOverride(scene, "diagnostic.knife_angle_deg=90");
    applyOverride(scene, "diagnostic.cutoff=colour");  // the knife's angle stays, unused
    const Scene parsed = parseScene(scene, "test.json");
    EXPECT_EQ(parsed.diagnostic->type, DiagnosticDesc::Type::Schlieren);
    EXPECT_EQ(parsed.diagnostic->cutoff, DiagnosticDesc::Cutoff::Colour);
    EXPECT_DOUBLE_EQ(parsed.diagnostic->knifeAngleDeg, 90.0);
    json bare = diagnosticScene({{"type", "schlieren"}});
    bare.erase("diagnostic");
    applyOverride(bare, "diagnostic.type=interferometry");
    applyOverride(bare, "diagnostic.wavelength_nm=633");
    EXPECT_DOUBLE_EQ(parseScene(bare, "test.json").diagnostic->wavelengthNm, 633.0);
    applyOverride(bare, "diagnostic.wavelength_nm=-1");
    expectErrorAt(bare, "diagnostic.wavelength_nm", "a number in (0, 1000000]");
    json shadow = diagnosticScene({{"type", "shadowgraph"}});
    applyOverride(shadow, "diagnostic.screen_distance=4");
    EXPECT_DOUBLE_EQ(parseScene(shadow, "test.json").diagnostic->screenDistance, 4.0);
    json bos = bosScene({{"type", "bos"}});
    applyOverride(bos, "diagnostic.seed=42");
    applyOverride(bos, "diagnostic.background_distance=0.5");
    EXPECT_EQ(parseScene(bos, "test.json").diagnostic->seed, 42u);
    EXPECT_DOUBLE_EQ(parseScene(bos, "test.json").diagnostic->backgroundDistance, 0.5);
}

}  // namespace
}  // namespace eikon
