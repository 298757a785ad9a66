// The frame graph: a stage runs only when one of its inputs changed, and a
// stage the scene does not need does not exist.
#include "io/scene/SceneParser.h"
#include "render/graph/FrameRenderer.h"
#include "sim/voxelize/AnalyticVoxelizer.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

namespace eikon {
namespace {

Scene smallDefaultScene(std::vector<std::string> overrides = {}) {
    overrides.insert(overrides.end(), {"grid.resolution=[24,20,24]", "render.photons=16384", "render.width=64",
                                       "render.height=48", "receivers.0.resolution=32"});
    return loadSceneFile(std::string(EIKON_SOURCE_DIR) + "/scenes/default.json", overrides);
}

std::set<std::string> stagesThatRan(const render::FrameResult& result) {
    std::set<std::string> ran;
    for (const auto& stage : result.stages)
        if (stage.ran) ran.insert(stage.name);
    return ran;
}

bool hasStage(const render::FrameResult& result, const std::string& name) {
    return std::any_of(result.stages.begin(), result.stages.end(),
                       [&](const render::StageReport& stage) { return stage.name == name; });
}

class FrameGraph : public ::testing::Test {
protected:
    void SetUp() override { test::glContext(); }
};

// The default scene's air is uniform: prepare and step_structure are
// written in closed form; one cell of graded δn makes them run.
TEST_F(FrameGraph, FirstFrameRunsEveryStageItHas) {
    const Scene scene = smallDefaultScene();
    FieldSet fields = sim::voxelizeScene(scene);
    {
        render::FrameRenderer renderer(scene, fields);
        const render::FrameResult result = renderer.render(fields);
        EXPECT_EQ(stagesThatRan(result), (std::set<std::string>{"upload", "photons", "view", "post"}));
        for (const auto& stage : result.stages) {
            if (stage.name == "prepare" || stage.name == "step_structure") {
                EXPECT_NE(stage.skippedBecause.find("uniform"), std::string::npos) << stage.name;
            }
        }
    }
    fields.deltaIndex.at(fields.grid.linearIndex(1, 2, 3)) = 1e-4f;
    render::FrameRenderer renderer(scene, fields);
    EXPECT_EQ(stagesThatRan(renderer.render(fields)),
              (std::set<std::string>{"upload", "prepare", "step_structure", "photons", "view", "post"}));
}

// Uniform δn but graded κ: prepare is written, the step structure runs.
TEST_F(FrameGraph, UniformIndexInAGradedMediumRunsTheStepStructure) {
    const Scene scene = smallDefaultScene({"tracer.estimator=\"photons\""});
    FieldSet fields = sim::voxelizeScene(scene);
    fields.extinction.assign(3 * fields.grid.cellCount(), 0.0f);
    fields.extinction.at(3 * fields.grid.linearIndex(4, 5, 6)) = 2.0f;
    render::FrameRenderer renderer(scene, fields);
    EXPECT_EQ(stagesThatRan(renderer.render(fields)),
              (std::set<std::string>{"upload", "step_structure", "photons", "view", "post"}));
}

TEST_F(FrameGraph, CameraOnlyChangeRunsOnlyViewAndPost) {
    const Scene scene = smallDefaultScene();
    const FieldSet fields = sim::voxelizeScene(scene);
    render::FrameRenderer renderer(scene, fields);
    const render::FrameResult first = renderer.render(fields);
    CameraDesc moved = scene.camera;
    moved.position.x += 0.5;
    renderer.setCamera(moved);
    const render::FrameResult second = renderer.render(fields);
    EXPECT_EQ(stagesThatRan(second), (std::set<std::string>{"view", "post"}));
    EXPECT_NE(first.image.rgba, second.image.rgba);  // the view did change
}

TEST_F(FrameGraph, MovingALightRunsPhotonsViewAndPost) {
    const Scene scene = smallDefaultScene();
    const FieldSet fields = sim::voxelizeScene(scene);
    render::FrameRenderer renderer(scene, fields);
    renderer.render(fields);
    const std::vector<float> before = renderer.receivers().download(0);
    LightDesc moved = scene.lights.at(0);
    moved.position.x += 0.3;
    renderer.setLight(0, moved);
    const render::FrameResult result = renderer.render(fields);
    EXPECT_EQ(stagesThatRan(result), (std::set<std::string>{"photons", "view", "post"}));
    EXPECT_NE(renderer.receivers().download(0), before);  // the caustic moved
}

TEST_F(FrameGraph, StaticSceneTracesPhotonsOnceInTenFrames) {
    const Scene scene = smallDefaultScene();
    const FieldSet fields = sim::voxelizeScene(scene);
    render::FrameRenderer renderer(scene, fields);
    int photonRuns = 0, uploads = 0;
    for (int frame = 0; frame < 10; ++frame) {
        const auto ran = stagesThatRan(renderer.render(fields));
        photonRuns += static_cast<int>(ran.count("photons"));
        uploads += static_cast<int>(ran.count("upload"));
    }
    EXPECT_EQ(photonRuns, 1);
    EXPECT_EQ(uploads, 1);
}

TEST_F(FrameGraph, UniformStepsHaveNoStepStructure) {
    const Scene scene = smallDefaultScene({"tracer.step_policy=uniform"});
    const FieldSet fields = sim::voxelizeScene(scene);
    render::FrameRenderer renderer(scene, fields);
    EXPECT_FALSE(hasStage(renderer.render(fields), "step_structure"));
}

TEST_F(FrameGraph, SceneWithNothingForPhotonsToLightHasNoPhotonStage) {
    Scene scene = smallDefaultScene();
    scene.receivers.clear();  // a clear glass sphere: no receivers, no scattering
    const FieldSet fields = sim::voxelizeScene(scene);
    render::FrameRenderer renderer(scene, fields);
    const render::FrameResult result = renderer.render(fields);
    EXPECT_EQ(renderer.photonStage(), nullptr);
    EXPECT_FALSE(hasStage(result, "photons"));
    EXPECT_TRUE(hasStage(result, "view"));
    // A light matters only through its photons: moving it here runs nothing.
    LightDesc moved = scene.lights.at(0);
    moved.position.x += 0.3;
    renderer.setLight(0, moved);
    EXPECT_TRUE(stagesThatRan(renderer.render(fields)).empty());
}

}  // namespace
}  // namespace eikon
