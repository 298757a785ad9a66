// Scene files from disk and --set overrides.
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

TEST(SceneFile, OverridesReachTheTracer) {
    const std::string path = writeTempFile("eikon_override_tracer.json", kValidScene);
    const Scene scene = loadSceneFile(path, {"tracer.integrator=euler", "tracer.renormalize=true"});
    EXPECT_EQ(scene.tracer.integrator, TracerDesc::Integrator::Euler);
    EXPECT_TRUE(scene.tracer.renormalize);
}

TEST(SceneFile, LoadsAFileAndRecordsItsPath) {
    const std::string path = writeTempFile("eikon_valid_scene.json", kValidScene);
    const Scene scene = loadSceneFile(path);
    EXPECT_EQ(scene.sourcePath, path);
    EXPECT_EQ(scene.objects.size(), 2u);
}

TEST(SceneFile, MissingFileNamesThePath) {
    const std::string path = ::testing::TempDir() + "eikon_no_such_scene.json";
    try {
        loadSceneFile(path);
        FAIL() << "no InputError";
    } catch (const InputError& error) {
        EXPECT_EQ(error.where(), path);
        EXPECT_NE(std::string(error.what()).find("no such file"), std::string::npos) << error.what();
    }
}

TEST(SceneFile, SyntaxErrorGivesLineAndColumn) {
    const std::string path = writeTempFile("eikon_syntax_error.json", "{\n  \"lights\": [],\n  \"grid\" {}\n}\n");
    try {
        loadSceneFile(path);
        FAIL() << "no InputError";
    } catch (const InputError& error) {
        EXPECT_EQ(error.where(), path + ": line 3, column 10");
        EXPECT_NE(std::string(error.what()).find("expected valid JSON, found syntax error"), std::string::npos)
            << error.what();
    }
}

// JSON parsers keep the last of a key given twice; a scene must not lose
// what was written first without a word.
TEST(SceneFile, DuplicateKeysAreRefusedWithTheirPath) {
    const std::string path = writeTempFile(
        "eikon_duplicate.json",
        R"({"lights": [], "objects": [{"type": "sphere"}, {"type": "sphere", "radius": 0.1, "radius": 0.2}]})");
    try {
        loadSceneFile(path);
        FAIL() << "no InputError";
    } catch (const InputError& error) {
        EXPECT_EQ(error.where(), path + ": objects[1].radius");
        EXPECT_NE(std::string(error.what()).find("twice"), std::string::npos) << error.what();
    }
}

TEST(SceneFile, NumberTooLargeForADouble) {
    const std::string path =
        writeTempFile("eikon_overflow.json", "{\"lights\": [],\n \"render\": {\"exposure_ev\": 1e999}}");
    try {
        loadSceneFile(path);
        FAIL() << "no InputError";
    } catch (const InputError& error) {
        EXPECT_EQ(error.where(), path + ": line 2, column 32");  // the number's last digit
        EXPECT_NE(std::string(error.what()).find("1e999"), std::string::npos) << error.what();
    }
}

TEST(SceneFile, OverrideIntoABadValueIsReportedAtItsPath) {
    const std::string path = writeTempFile("eikon_override_scene.json", kValidScene);
    try {
        loadSceneFile(path, {"render.photons=-5"});
        FAIL() << "no InputError";
    } catch (const InputError& error) {
        EXPECT_EQ(error.where(), path + ": render.photons");
        EXPECT_NE(std::string(error.what()).find("found -5"), std::string::npos) << error.what();
    }
}

TEST(SceneFile, OverridesApplyInOrder) {
    const std::string path = writeTempFile("eikon_override_order.json", kValidScene);
    const Scene scene = loadSceneFile(path, {"objects.0.radius=0.3", "render.width=100", "render.width=200"});
    EXPECT_DOUBLE_EQ(scene.objects[0].sphere.radius, 0.3);
    EXPECT_EQ(scene.render.width, 200);
}

TEST(ApplyOverride, SetsNestedAndArrayIndexedValues) {
    json root = validScene();
    applyOverride(root, "render.photons=1000");
    applyOverride(root, "objects.1.min=[-1,-2,-3]");
    applyOverride(root, "lights.0.type=directional");
    applyOverride(root, "grid.extra.deep=true");
    EXPECT_EQ(root["render"]["photons"], 1000);
    EXPECT_EQ(root["objects"][1]["min"], json({-1, -2, -3}));
    EXPECT_EQ(root["lights"][0]["type"], "directional");  // not JSON, so taken as a string
    EXPECT_EQ(root["grid"]["extra"]["deep"], true);       // intermediate object created
}

// The `where` of the InputError that applying `assignment` throws.
std::string overrideErrorWhere(const std::string& assignment) {
    json root = validScene();
    try {
        applyOverride(root, assignment);
    } catch (const InputError& error) {
        return error.where();
    }
    ADD_FAILURE() << "applyOverride accepted " << assignment;
    return "";
}

TEST(ApplyOverride, RejectsMalformedAssignments) {
    for (const std::string assignment : {"render.photons", "=5", "render..photons=5", "objects.2.radius=1",
                                         "render.photons.x=1", "objects.first=1"}) {
        EXPECT_EQ(overrideErrorWhere(assignment), "--set " + assignment);
    }
}

// --- sim: the built-in fluid solver ------------------------------------------

}  // namespace
}  // namespace eikon
