// Mesh and water objects in SceneFields: deformed every frame, repainted
// only where they moved, composited in list order with spheres and boxes.
#include "sim/SceneFields.h"

#include "bridge/mesh/TriangleBvh.h"

#include "sim/deform/MeshShapes.h"
#include "sim/voxelize/Compositor.h"
#include "sim/voxelize/MeshCoverage.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>

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

// Each frame says where its fields changed (FieldChange), so the GPU's
// copies of the frame before take only those cells: every cell that
// differs lies in the box, and the box is a small part of the grid.
TEST(SceneFieldsMesh, EachFrameNamesTheCellsItChanged) {
    const Scene scene = twistingBarScene();
    SceneFields fields(scene);
    const GridSpec& grid = fields.fields().grid;
    for (int frame = 0; frame < 3; ++frame) {
        const FieldSet before = fields.fields();
        fields.advanceFrame();
        const FieldSet& after = fields.fields();
        ASSERT_EQ(after.indexVersion, before.indexVersion + 1);
        EXPECT_TRUE(after.indexChange.onlyCellsSince(before.indexVersion, after.indexVersion));
        EXPECT_TRUE(after.extinctionChange.onlyCellsSince(before.extinctionVersion, after.extinctionVersion));
        EXPECT_FALSE(after.indexChange.onlyCellsSince(before.indexVersion - 1, after.indexVersion))
            << "two versions behind: the change says nothing about the one between";
        const CellBox box = after.indexChange.cells;
        EXPECT_LT(box.cellCount(), static_cast<long long>(grid.cellCount() / 2));
        long long differing = 0;
        for (int k = 0; k < grid.resolution.z; ++k)
            for (int j = 0; j < grid.resolution.y; ++j)
                for (int i = 0; i < grid.resolution.x; ++i) {
                    const std::size_t cell = grid.linearIndex(i, j, k);
                    const bool changed = before.deltaIndex[cell] != after.deltaIndex[cell] ||
                                         before.extinction[3 * cell] != after.extinction[3 * cell];
                    if (!changed) continue;
                    ++differing;
                    const glm::ivec3 c(i, j, k);
                    ASSERT_TRUE(glm::all(glm::greaterThanEqual(c, box.min)) && glm::all(glm::lessThan(c, box.max)))
                        << "cell (" << i << ", " << j << ", " << k << ") changed outside the box";
                }
        EXPECT_GT(differing, 0) << "the bar twists every frame";
    }
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
// triangles instead, in a tree (sim/SharpMeshSurfaces.h): every triangle
// once, each inside its leaf's box and each box inside its parent's; corner
// normals that are the faces' own on the bar's flat faces and at its 90°
// edges; republished (and only then) as it deforms.
TEST(SceneFieldsMesh, SharpMeshPublishesItsTriangleTree) {
    Scene scene = twistingBarScene();
    scene.objects[0].surface = ObjectDesc::Surface::Sharp;
    SceneFields fields(scene);
    const FieldSet& set = fields.fields();
    const GridSpec& grid = set.grid;
    const TriangleMesh& mesh = *fields.deformedMeshes()[0];
    const std::size_t triangles = set.surfaceTriangles.size() / kSurfaceTriangleFloats;
    const std::size_t nodes = set.surfaceNodes.size() / kSurfaceNodeFloats;
    ASSERT_EQ(triangles, mesh.triangles.size());
    ASSERT_GE(nodes, 2 * triangles / TriangleBvh::kLeafTriangles - 1);
    EXPECT_NO_THROW(validateFields(set, [](std::string_view, const glm::dvec3*) { return std::string("test"); }));
    EXPECT_EQ(set.deltaIndex[grid.linearIndex(24, 24, 24)], 0.0f) << "no index voxelized";
    EXPECT_GT(set.extinction[3 * grid.linearIndex(24, 24, 24)], 0.0f) << "its extinction is";

    auto node = [&](std::size_t n) { return set.surfaceNodes.data() + n * kSurfaceNodeFloats; };
    auto corner = [&](std::size_t t, int c) {
        const float* v = set.surfaceTriangles.data() + t * kSurfaceTriangleFloats + 4 * c;
        return glm::dvec3(v[0], v[1], v[2]);
    };
    EXPECT_NEAR(node(0)[0], -0.1, 1e-6);
    EXPECT_NEAR(node(0)[5], 0.4, 1e-6);
    std::vector<int> seen(triangles, 0);
    std::vector<std::size_t> pending = {0};
    while (!pending.empty()) {
        const std::size_t n = pending.back();
        pending.pop_back();
        const float* box = node(n);
        const auto first = static_cast<std::size_t>(box[3]), count = static_cast<std::size_t>(box[7]);
        auto inside = [&](const float* child) {
            for (int axis = 0; axis < 3; ++axis)
                if (child[axis] < box[axis] || child[4 + axis] > box[4 + axis]) return false;
            return true;
        };
        if (count == 0) {
            ASSERT_GT(first, 0u) << "the root is no node's child";
            ASSERT_LT(first + 1, nodes);
            EXPECT_TRUE(inside(node(first)) && inside(node(first + 1))) << "node " << n;
            pending.push_back(first);
            pending.push_back(first + 1);
            continue;
        }
        for (std::size_t t = first; t < first + count; ++t) {
            ASSERT_LT(t, triangles);
            ++seen[t];
            for (int c = 0; c < 3; ++c)
                for (int axis = 0; axis < 3; ++axis) {
                    EXPECT_GE(corner(t, c)[axis], box[axis]);
                    EXPECT_LE(corner(t, c)[axis], box[4 + axis]);
                }
        }
    }
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<std::ptrdiff_t>(triangles)) << "each triangle once";
    for (std::size_t t = 0; t < triangles; ++t) {
        const glm::dvec3 facet = glm::normalize(glm::cross(corner(t, 1) - corner(t, 0), corner(t, 2) - corner(t, 0)));
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(std::abs(glm::dot(corner(t, 3 + c), facet)), 1.0, 1e-6) << "a box has no smooth corner";
    }

    const std::uint64_t version = set.surfaceVersion;
    const std::vector<float> before = set.surfaceTriangles;
    fields.advanceFrame();
    EXPECT_GT(fields.fields().surfaceVersion, version);
    EXPECT_NE(fields.fields().surfaceTriangles, before) << "the bar twists";
    Scene still = twistingBarScene();
    still.objects[0].surface = ObjectDesc::Surface::Sharp;
    still.objects[0].mesh.deformer = {};
    SceneFields stillFields(still);
    const std::uint64_t stillVersion = stillFields.fields().surfaceVersion;
    stillFields.advanceFrame();
    EXPECT_EQ(stillFields.fields().surfaceVersion, stillVersion) << "nothing moved: nothing to upload";
}

// Image space draws a sharp mesh's surface, not its voxel coverage: such a
// scene skips the coverage (and the extinction painted from it) while its
// triangles still follow the deformation; once kept again, the coverage
// catches up, and the fields equal those of a run that kept it throughout.
TEST(SceneFieldsMesh, ImageSpaceSkipsTheSharpCoverageUntilItIsKept) {
    Scene eikonal = twistingBarScene();
    eikonal.objects[0].surface = ObjectDesc::Surface::Sharp;
    Scene imageSpace = eikonal;
    imageSpace.render.method = RenderDesc::Method::ImageSpace;
    EXPECT_TRUE(SceneFields::needsSharpCoverage(eikonal));
    EXPECT_FALSE(SceneFields::needsSharpCoverage(imageSpace));
    Scene exported = imageSpace;
    exported.exports.vtk.enabled = true;
    EXPECT_TRUE(SceneFields::needsSharpCoverage(exported)) << "exports read the fields";

    SceneFields kept(eikonal), skipped(imageSpace);
    const GridSpec& grid = kept.fields().grid;
    EXPECT_EQ(skipped.fields().extinction[3 * grid.linearIndex(24, 24, 24)], 0.0f) << "no coverage painted";
    const std::uint64_t surfaceVersion = skipped.fields().surfaceVersion, indexVersion = skipped.fields().indexVersion;
    for (int frame = 0; frame < 2; ++frame) {
        kept.advanceFrame();
        skipped.advanceFrame();
    }
    EXPECT_EQ(skipped.fields().surfaceVersion, surfaceVersion + 2) << "refitted every frame";
    EXPECT_EQ(skipped.fields().indexVersion, indexVersion) << "no field to upload";
    EXPECT_EQ(skipped.fields().surfaceTriangles, kept.fields().surfaceTriangles);
    EXPECT_EQ(skipped.fields().surfaceNodes, kept.fields().surfaceNodes);
    EXPECT_EQ(skipped.lastTimings()[1].iterations, 0) << "no cells recomputed";

    skipped.keepSharpCoverage(true);
    EXPECT_GT(skipped.fields().indexVersion, indexVersion);
    EXPECT_EQ(skipped.fields().deltaIndex, kept.fields().deltaIndex);
    EXPECT_EQ(skipped.fields().extinction, kept.fields().extinction);
    kept.advanceFrame();
    skipped.advanceFrame();
    EXPECT_EQ(skipped.fields().extinction, kept.fields().extinction) << "and keeps up afterwards";
}

}  // namespace
}  // namespace eikon::sim
