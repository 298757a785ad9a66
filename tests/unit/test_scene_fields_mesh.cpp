// Mesh and water objects in SceneFields: deformed every frame, repainted
// only where they moved, composited in list order with spheres and boxes.
#include "sim/SceneFields.h"

#include "sim/deform/MeshShapes.h"
#include "sim/voxelize/Compositor.h"
#include "sim/voxelize/MeshCoverage.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace eikon::sim {
namespace {

// Named after the running test: ctest runs tests in parallel processes.
std::string writeOff(const TriangleMesh& mesh, const std::string& name) {
    const std::string path =
        ::testing::TempDir() + ::testing::UnitTest::GetInstance()->current_test_info()->name() + "_" + name;
    std::ofstream off(path);
    off.precision(17);
    off << "OFF\n" << mesh.vertices.size() << " " << mesh.triangles.size() << " 0\n";
    for (const glm::dvec3& v : mesh.vertices) off << v.x << " " << v.y << " " << v.z << "\n";
    for (const glm::ivec3& t : mesh.triangles) off << "3 " << t.x << " " << t.y << " " << t.z << "\n";
    return path;
}

Scene twistingBarScene() {
    Scene scene;
    scene.grid.resolution = glm::ivec3(48);
    scene.grid.boundsMin = glm::dvec3(-0.6);
    scene.grid.boundsMax = glm::dvec3(0.6);
    ObjectDesc bar;
    bar.kind = ObjectDesc::Kind::Mesh;
    bar.mesh.path = writeOff(boxMesh(glm::dvec3(-0.1, -0.4, -0.1), glm::dvec3(0.1, 0.4, 0.1), glm::ivec3(4, 16, 4)),
                             "bar.off");
    bar.mesh.deformer.kind = DeformerDesc::Kind::Twist;
    bar.mesh.deformer.axis = glm::dvec3(0, 1, 0);
    bar.mesh.deformer.amount = {{0.0, 0.0}, {1.0, 300.0}};
    bar.material.index = 1.5;
    bar.material.extinction = Rgb(1.0, 2.0, 3.0);
    bar.surface = ObjectDesc::Surface::Smooth;  // voxelized into the index
    scene.objects.push_back(bar);
    scene.frameTime = 0.1;
    return scene;
}

TEST(SceneFieldsMesh, DeformsEachFrameAndMatchesAFullRepaint) {
    const Scene scene = twistingBarScene();
    SceneFields fields(scene);
    EXPECT_TRUE(fields.changesOverTime());
    ASSERT_EQ(fields.deformedMeshes().size(), 1u);
    const std::uint64_t version = fields.fields().indexVersion;
    fields.advanceFrame();
    fields.advanceFrame();
    EXPECT_DOUBLE_EQ(fields.time(), 0.2);
    EXPECT_EQ(fields.fields().indexVersion, version + 2);
    const auto timings = fields.lastTimings();
    ASSERT_EQ(timings.size(), 2u);
    EXPECT_EQ(timings[1].phase, "voxelize");
    EXPECT_GT(timings[1].iterations, 0) << "cells recomputed";
    EXPECT_LT(timings[1].iterations, 48 * 48 * 48 / 2) << "only the bar's neighbourhood";

    // A full repaint of the frame's deformed mesh gives the same fields.
    MeshCoverage coverage(fields.fields().grid);
    coverage.update(*fields.deformedMeshes()[0]);
    FieldSet full;
    full.grid = fields.fields().grid;
    full.deltaIndex.assign(full.grid.cellCount(), 0.0f);
    fillMedium(scene, full, CellBox::whole(full.grid));
    paintObjects(scene, full, {&coverage.values()});
    ASSERT_EQ(full.deltaIndex.size(), fields.fields().deltaIndex.size());
    for (std::size_t cell = 0; cell < full.deltaIndex.size(); ++cell)
        ASSERT_EQ(full.deltaIndex[cell], fields.fields().deltaIndex[cell]) << "cell " << cell;
    EXPECT_EQ(full.extinction, fields.fields().extinction);
}

TEST(SceneFieldsMesh, ObjectsCompositeInListOrderWhateverTheirKind) {
    Scene scene = twistingBarScene();
    scene.objects[0].mesh.deformer = {};
    ObjectDesc sphere;
    sphere.kind = ObjectDesc::Kind::Sphere;
    sphere.surface = ObjectDesc::Surface::Smooth;  // voxelized into the index, as the bar is
    sphere.sphere = {glm::dvec3(0.0), 0.05};
    sphere.material.index = 2.0;
    scene.objects.push_back(sphere);  // inside the bar, listed after it: it wins
    const SceneFields fields(scene);
    EXPECT_FALSE(fields.changesOverTime());
    const GridSpec& grid = fields.fields().grid;
    EXPECT_FLOAT_EQ(fields.fields().deltaIndex[grid.linearIndex(24, 24, 24)], 1.0f);  // the sphere's n − 1
    EXPECT_FLOAT_EQ(fields.fields().deltaIndex[grid.linearIndex(24, 10, 24)], 0.5f);  // the bar's
}

// Any finite placement works: a deforming mesh a million kilometres from the
// grid covers no cell, frame after frame (its cell boxes once overflowed int).
TEST(SceneFieldsMesh, MeshFarOutsideTheGridCoversNothing) {
    for (double offset : {1e9, -1e9, 1e300}) {
        Scene scene = twistingBarScene();
        scene.objects[0].mesh.placement.translate = glm::dvec3(offset, 0.0, 0.0);
        SceneFields fields(scene);
        fields.advanceFrame();
        for (float delta : fields.fields().deltaIndex) ASSERT_EQ(delta, 0.0f) << offset;
    }
}

TEST(SceneFieldsMesh, WaterMovesWithSceneTime) {
    Scene scene;
    scene.grid.resolution = glm::ivec3(32, 16, 32);
    scene.grid.boundsMin = glm::dvec3(-0.5, 0.0, -0.5);
    scene.grid.boundsMax = glm::dvec3(0.5, 0.5, 0.5);
    ObjectDesc water;
    water.kind = ObjectDesc::Kind::Water;
    water.water.basinMin = glm::dvec3(-0.6, -0.1, -0.6);
    water.water.basinMax = glm::dvec3(0.6, 0.25, 0.6);
    water.water.cells = glm::ivec2(40, 40);
    water.water.swellAmplitude = 0.01;
    water.water.swellWavelength = 0.3;
    water.material.index = 1.333;
    water.surface = ObjectDesc::Surface::Smooth;  // voxelized into the index
    scene.objects.push_back(water);
    scene.frameTime = 0.05;
    SceneFields fields(scene);
    const std::vector<float> before = fields.fields().deltaIndex;
    fields.advanceFrame();
    EXPECT_NE(fields.fields().deltaIndex, before);
    EXPECT_NEAR(fields.fields().deltaIndex[fields.fields().grid.linearIndex(16, 2, 16)], 0.333f, 1e-6) << "deep water";
    EXPECT_EQ(fields.fields().deltaIndex[fields.fields().grid.linearIndex(16, 14, 16)], 0.0f) << "air above";
}

// A sharp mesh keeps its index out of the field and hands the tracers its
// signed distance instead: one layer, negative inside, clamped to the band,
// bounds that hold the bar, republished (and only then) as it deforms.
TEST(SceneFieldsMesh, SharpMeshPublishesItsDistanceLayer) {
    Scene scene = twistingBarScene();
    scene.objects[0].surface = ObjectDesc::Surface::Sharp;
    SceneFields fields(scene);
    const FieldSet& set = fields.fields();
    const GridSpec& grid = set.grid;
    ASSERT_EQ(set.surfaceLayers(), 1u);
    ASSERT_EQ(set.surfaceDistance.size(), grid.cellCount());
    EXPECT_NO_THROW(validateFields(set, "test"));
    EXPECT_EQ(set.deltaIndex[grid.linearIndex(24, 24, 24)], 0.0f) << "no index voxelized";
    EXPECT_GT(set.extinction[3 * grid.linearIndex(24, 24, 24)], 0.0f) << "its extinction is";
    const double h = grid.smallestVoxelEdge();
    const float band = set.surfaceDistance[grid.linearIndex(0, 0, 0)];
    EXPECT_GT(band, 0.0f) << "far outside";
    EXPECT_EQ(set.surfaceDistance[grid.linearIndex(24, 24, 24)], -band) << "deep inside, clamped";
    // Cells (28, 24, 24) and (27, 24, 24) have their centres at x = 0.1125
    // and 0.0875, half a cell either side of the face x = 0.1.
    EXPECT_NEAR(set.surfaceDistance[grid.linearIndex(28, 24, 24)], 0.5 * h, 1e-3 * h);
    EXPECT_NEAR(set.surfaceDistance[grid.linearIndex(27, 24, 24)], -0.5 * h, 1e-3 * h);
    EXPECT_LE(set.surfaceBounds[0], -0.1);
    EXPECT_GE(set.surfaceBounds[4], 0.4);
    const std::uint64_t version = set.surfaceVersion;
    const std::vector<float> before = set.surfaceDistance;
    fields.advanceFrame();
    EXPECT_GT(fields.fields().surfaceVersion, version);
    EXPECT_NE(fields.fields().surfaceDistance, before) << "the bar twists";
    Scene still = twistingBarScene();
    still.objects[0].surface = ObjectDesc::Surface::Sharp;
    still.objects[0].mesh.deformer = {};
    SceneFields stillFields(still);
    const std::uint64_t stillVersion = stillFields.fields().surfaceVersion;
    stillFields.advanceFrame();
    EXPECT_EQ(stillFields.fields().surfaceVersion, stillVersion) << "nothing moved: nothing to upload";
}

}  // namespace
}  // namespace eikon::sim
