// Coverage of meshes voxelized through the band-limited signed distance
// (OpenVDB's unsigned distance of the triangles near the cells redone, signed
// by row parity): Σ coverage·h³ against closed-form volumes, and the
// band-limited update against a full recomputation.
#include "sim/deform/MeshShapes.h"
#include "sim/voxelize/MeshCoverage.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace eikon::sim {
namespace {

const GridSpec kGrid64{glm::ivec3(64), glm::dvec3(-1.0), glm::dvec3(1.0)};

// Acceptance (issue): a sphere of radius R at 64³ within 1% of 4/3·π·R³.
// The mesh itself falls short of the sphere by its facets (≈ 0.1% here), so
// the coverage is also checked against the mesh's own volume.
TEST(MeshCoverage, SphereVolumeWithinOnePercentAt64) {
    const double radius = 0.6;
    const TriangleMesh mesh = sphereMesh(glm::dvec3(0.03, -0.02, 0.01), radius, 96, 192);
    MeshCoverage coverage(kGrid64);
    coverage.update(mesh);
    const double exact = 4.0 / 3.0 * std::numbers::pi * std::pow(radius, 3);
    const double error = coverage.coveredVolume() / exact - 1.0;
    RecordProperty("sphere_relative_error", std::to_string(error));
    EXPECT_NEAR(error, 0.0, 0.01);
    EXPECT_NEAR(coverage.coveredVolume() / enclosedVolume(mesh), 1.0, 0.005);
}

TEST(MeshCoverage, TorusVolumeWithinOnePercentAt64) {
    const double major = 0.55, minor = 0.25;
    const TriangleMesh mesh = torusMesh(glm::dvec3(0.02, 0.01, -0.03), major, minor, 256, 96);
    MeshCoverage coverage(kGrid64);
    coverage.update(mesh);
    const double exact = 2.0 * std::numbers::pi * std::numbers::pi * major * minor * minor;
    const double error = coverage.coveredVolume() / exact - 1.0;
    RecordProperty("torus_relative_error", std::to_string(error));
    EXPECT_NEAR(error, 0.0, 0.01);
    // The hole is empty: the cell at the centre of the torus is outside.
    EXPECT_NEAR(coverage.values()[kGrid64.linearIndex(32, 32, 31)], 0.0, 1e-5);
}

// Faces on voxel boundaries (h = 1/32): cells along a face are exactly 0 or
// 1 (only the cells at the box's edges see a diagonal distance gradient), up
// to float rounding of φ.
TEST(MeshCoverage, AlignedFacesGiveWholeCells) {
    MeshCoverage coverage(kGrid64);
    coverage.update(boxMesh(glm::dvec3(-0.5), glm::dvec3(0.5, 0.5, 0.25), glm::ivec3(2)));
    EXPECT_NEAR(coverage.values()[kGrid64.linearIndex(32, 32, 39)], 1.0, 1e-5);  // just inside z = 0.25
    EXPECT_NEAR(coverage.values()[kGrid64.linearIndex(32, 32, 40)], 0.0, 1e-5);  // just outside
    EXPECT_NEAR(coverage.values()[kGrid64.linearIndex(16, 20, 20)], 1.0, 1e-5);  // just inside x = -0.5
    EXPECT_NEAR(coverage.values()[kGrid64.linearIndex(15, 20, 20)], 0.0, 1e-5);
    // The linear model rounds the box's 12 sharp edges a little (−0.34% measured).
    EXPECT_NEAR(coverage.coveredVolume() / 0.75, 1.0, 0.005);
}

// Raising a water-like slab by a tenth of a voxel adds a tenth of a voxel
// layer of volume: coverage follows sub-voxel motion continuously (4³
// supersampling would move in quarter-voxel steps and see nothing here).
TEST(MeshCoverage, FollowsSubVoxelMotionContinuously) {
    const double h = 2.0 / 64;
    const double top = 0.1 + 0.3 * h;
    MeshCoverage before(kGrid64), after(kGrid64);
    before.update(boxMesh(glm::dvec3(-0.5, -0.5, -0.5), glm::dvec3(0.5, top, 0.5), glm::ivec3(4)));
    after.update(boxMesh(glm::dvec3(-0.5, -0.5, -0.5), glm::dvec3(0.5, top + 0.1 * h, 0.5), glm::ivec3(4)));
    const double added = after.coveredVolume() - before.coveredVolume();
    EXPECT_NEAR(added / (0.1 * h * 1.0), 1.0, 0.02);
}

// Moving a part of the mesh recomputes only a box around that part, from
// the distance of only the triangles near it, and the result equals a fresh
// voxelization of the moved mesh (bit for bit today; the tolerance leaves
// room for OpenVDB, which splits triangles longer than 16 voxels only in
// meshes of under 1000, to round a sub-mesh's distances differently).
TEST(MeshCoverage, BandLimitedUpdateMatchesAFullRecomputation) {
    TriangleMesh mesh = sphereMesh(glm::dvec3(0.0), 0.5, 48, 96);
    MeshCoverage incremental(kGrid64);
    const CellBlocks first = incremental.update(mesh);
    EXPECT_FALSE(first.empty());
    EXPECT_EQ(incremental.lastDistanceTriangles(), mesh.triangles.size()) << "the first update sees every triangle";

    EXPECT_TRUE(incremental.update(mesh).empty()) << "nothing moved, nothing recomputed";

    for (glm::dvec3& v : mesh.vertices)
        if (v.y > 0.4) v.y += 0.05 * (v.y - 0.4) / 0.1;  // lift the north cap
    const CellBlocks moved = incremental.update(mesh);
    EXPECT_GT(moved.cellCount(), 0);
    EXPECT_LT(moved.cellCount(), first.cellCount() / 4) << "only the band around the cap";
    for (const CellBox& block : moved.boxes()) EXPECT_GE(block.min.y, 40) << "the cap lies above y = 0.3";
    // The blocks above y = 0.25 m and 4.5 voxels around them: 44% of the
    // triangles (a latitude–longitude sphere crowds them at its poles).
    EXPECT_LT(incremental.lastDistanceTriangles(), mesh.triangles.size() / 2) << "only the triangles near the cap";

    MeshCoverage fresh(kGrid64);
    fresh.update(mesh);
    for (std::size_t cell = 0; cell < fresh.values().size(); ++cell)
        ASSERT_NEAR(incremental.values()[cell], fresh.values()[cell], 1e-6) << "cell " << cell;
}

// The same on voxels that are not cubes, over a box whose corner is off the
// lattice of OpenVDB's voxels (cubes of the smallest edge): the reach of the
// cells' samples and the wider band (3 voxels here) are counted in the grid's
// own terms. A dent with a hard rim pulls on triangles that also hold
// vertices that stay.
TEST(MeshCoverage, BandLimitedUpdateMatchesOnNonCubicVoxels) {
    const GridSpec grid{glm::ivec3(70, 50, 61), glm::dvec3(-0.513, -0.47, -0.52), glm::dvec3(0.49, 0.53, 0.5)};
    const TriangleMesh rest = sphereMesh(glm::dvec3(0.013, -0.007, 0.004), 0.35, 48, 96);
    MeshCoverage incremental(grid);
    incremental.update(rest);
    for (double depth : {0.02, -0.015}) {
        TriangleMesh mesh = rest;
        for (glm::dvec3& v : mesh.vertices)
            if (glm::length(v - glm::dvec3(0.35, 0.05, 0.0)) < 0.12) v *= 1.0 - depth / 0.35;
        incremental.update(mesh);
        EXPECT_LT(incremental.lastDistanceTriangles(), mesh.triangles.size() / 2);
        MeshCoverage fresh(grid);
        fresh.update(mesh);
        for (std::size_t cell = 0; cell < fresh.values().size(); ++cell)
            ASSERT_NEAR(incremental.values()[cell], fresh.values()[cell], 1e-6) << "cell " << cell;
    }
}

// The acceptance volumes again, reached through a band-limited update: a
// dent pressed into one side of the solid and released again, so that the
// last update computes the distance of the triangles near the dent only.
TEST(MeshCoverage, VolumesWithinOnePercentAfterALocalDeformation) {
    struct Case {
        TriangleMesh mesh;
        double exact;
    };
    const double radius = 0.6, major = 0.55, minor = 0.25;
    const Case cases[] = {
        {sphereMesh(glm::dvec3(0.03, -0.02, 0.01), radius, 96, 192), 4.0 / 3.0 * std::numbers::pi * std::pow(radius, 3)},
        {torusMesh(glm::dvec3(0.02, 0.01, -0.03), major, minor, 256, 96),
         2.0 * std::numbers::pi * std::numbers::pi * major * minor * minor}};
    for (const Case& c : cases) {
        TriangleMesh dented = c.mesh;
        for (glm::dvec3& v : dented.vertices)
            if (v.x > 0.5) v.x -= 0.5 * (v.x - 0.5);
        MeshCoverage coverage(kGrid64);
        coverage.update(dented);
        coverage.update(c.mesh);
        EXPECT_LT(coverage.lastDistanceTriangles(), c.mesh.triangles.size() / 2);
        EXPECT_NEAR(coverage.coveredVolume() / c.exact - 1.0, 0.0, 0.01);
        MeshCoverage fresh(kGrid64);
        fresh.update(c.mesh);
        for (std::size_t cell = 0; cell < fresh.values().size(); ++cell)
            ASSERT_NEAR(coverage.values()[cell], fresh.values()[cell], 1e-6) << "cell " << cell;
    }
}

TEST(MeshShapes, GeneratedSolidsAreClosedAndOutward) {
    for (const TriangleMesh& mesh : {sphereMesh(glm::dvec3(0), 1, 8, 12), torusMesh(glm::dvec3(0), 1, 0.3, 16, 8),
                                     boxMesh(glm::dvec3(0), glm::dvec3(1, 2, 3), glm::ivec3(2, 3, 4))}) {
        EXPECT_TRUE(countEdges(mesh).closedManifold());
        EXPECT_GT(enclosedVolume(mesh), 0.0);
    }
    EXPECT_NEAR(enclosedVolume(boxMesh(glm::dvec3(0), glm::dvec3(1, 2, 3), glm::ivec3(2, 3, 4))), 6.0, 1e-12);
}

}  // namespace
}  // namespace eikon::sim
