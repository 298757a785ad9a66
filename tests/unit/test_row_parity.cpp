// Ray parity along grid rows (RowParity): crossings of closed meshes where
// they can be counted by hand — rows through vertices, along edges and in
// the planes of faces — even counts on meshes whose every vertex lies on a
// row, and inside/outside of a sphere and a torus against their equations.
#include "sim/deform/MeshShapes.h"
#include "sim/voxelize/RowParity.h"

#include <gtest/gtest.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <utility>

namespace eikon::sim {
namespace {

std::vector<double> crossingsOf(const TriangleMesh& mesh, int j, int k, int range = 20) {
    const RowParity parity(mesh.vertices, mesh.triangles, glm::ivec2(-range), glm::ivec2(range));
    std::vector<double> xs;
    parity.crossings(j, k, xs);
    return xs;
}

// Octahedron |x| + |y| + |z| ≤ 3: its six vertices lie on rows.
TriangleMesh octahedron() {
    TriangleMesh mesh;
    mesh.vertices = {{3, 0, 0}, {-3, 0, 0}, {0, 3, 0}, {0, -3, 0}, {0, 0, 3}, {0, 0, -3}};
    for (int sx = 0; sx < 2; ++sx)
        for (int sy = 2; sy < 4; ++sy)
            for (int sz = 4; sz < 6; ++sz) mesh.triangles.emplace_back(sx, sy, sz);
    return mesh;
}

// A box with corners on rows and faces split 2×2: rows along its faces, its
// edges and through its vertices. A row on the box's boundary counts as the
// point (j + ε, k + ε²) would: inside on the low sides, outside on the high.
TEST(RowParity, BoxIsCrossedOnceByEachEndFace) {
    const TriangleMesh box = boxMesh(glm::dvec3(0), glm::dvec3(4), glm::ivec3(2));
    for (int k = -1; k <= 5; ++k)
        for (int j = -1; j <= 5; ++j) {
            const std::vector<double> xs = crossingsOf(box, j, k);
            if (j >= 0 && j < 4 && k >= 0 && k < 4)
                EXPECT_EQ(xs, (std::vector<double>{0.0, 4.0})) << "row " << j << ", " << k;
            else
                EXPECT_TRUE(xs.empty()) << "row " << j << ", " << k;
        }
}

TEST(RowParity, RowsThroughVerticesAndAlongEdgesCountOnce) {
    const TriangleMesh mesh = octahedron();
    // Through the vertices (±3, 0, 0), where four triangles meet.
    EXPECT_EQ(crossingsOf(mesh, 0, 0), (std::vector<double>{-3.0, 3.0}));
    // In the plane z = 0, through the edges shared by the triangles above
    // and below it.
    EXPECT_EQ(crossingsOf(mesh, 1, 0), (std::vector<double>{-2.0, 2.0}));
    EXPECT_EQ(crossingsOf(mesh, 0, -2), (std::vector<double>{-1.0, 1.0}));
    // Grazing the apex (0, 3, 0) and (0, 0, 3) from outside: no crossing.
    EXPECT_TRUE(crossingsOf(mesh, 3, 0).empty());
    EXPECT_TRUE(crossingsOf(mesh, 0, 3).empty());
    // Through a face's interior.
    EXPECT_EQ(crossingsOf(mesh, 1, 1), (std::vector<double>{-1.0, 1.0}));
    // Along silhouette edges, where the triangles before and behind the edge
    // meet and both project to the same side of it: the edge from (0, −3, 0)
    // to (0, 0, −3) is entered and left at x = 0; the one from (0, 3, 0) to
    // (0, 0, 3) is missed.
    const std::vector<double> silhouette = crossingsOf(mesh, -2, -1);
    ASSERT_EQ(silhouette.size(), 2u);
    EXPECT_EQ(silhouette[0], 0.0);
    EXPECT_EQ(silhouette[1], 0.0);
    EXPECT_TRUE(crossingsOf(mesh, 2, 1).empty());
}

// The same crossings, up to rounding of the barycentric sums.
TEST(RowParity, WindingDoesNotMatter) {
    TriangleMesh flipped = sphereMesh(glm::dvec3(0.2, 0.1, -0.3), 6.5, 12, 24);
    const TriangleMesh outward = flipped;
    for (glm::ivec3& t : flipped.triangles) std::swap(t.y, t.z);
    for (int k = -8; k <= 8; ++k)
        for (int j = -8; j <= 8; ++j) {
            const std::vector<double> a = crossingsOf(flipped, j, k), b = crossingsOf(outward, j, k);
            ASSERT_EQ(a.size(), b.size()) << "row " << j << ", " << k;
            for (std::size_t n = 0; n < a.size(); ++n) EXPECT_NEAR(a[n], b[n], 1e-12);
        }
}

// Every vertex rounded to integers: rows run through vertices, along edges
// and inside faces in all the ways a mesh can meet them (some triangles even
// collapse to segments). A closed mesh is still crossed an even number of
// times on every row.
TEST(RowParity, MeshesWithEveryVertexOnARowAreCrossedEvenly) {
    for (TriangleMesh mesh : {sphereMesh(glm::dvec3(0), 6.2, 10, 20), torusMesh(glm::dvec3(0), 5.0, 2.4, 24, 12),
                              sphereMesh(glm::dvec3(0.5, 0, 0), 3.0, 6, 8)}) {
        for (glm::dvec3& v : mesh.vertices) v = glm::round(v);
        const RowParity parity(mesh.vertices, mesh.triangles, glm::ivec2(-9), glm::ivec2(9));
        std::vector<double> xs;
        int crossedRows = 0;
        for (int k = -9; k <= 9; ++k)
            for (int j = -9; j <= 9; ++j) {
                parity.crossings(j, k, xs);
                EXPECT_EQ(xs.size() % 2, 0u) << "row " << j << ", " << k;
                crossedRows += !xs.empty();
            }
        EXPECT_GT(crossedRows, 20);
    }
}

// Inside by parity against the solids' equations, for points farther from
// the surface than the meshes' facets stray from it.
TEST(RowParity, InsideOfSphereAndTorusMatchesTheirEquations) {
    const glm::dvec3 centre(0.31, 0.17, -0.23);
    const double radius = 9.6, major = 7.0, minor = 3.0;
    const TriangleMesh sphere = sphereMesh(centre, radius, 48, 96);
    const TriangleMesh torus = torusMesh(centre, major, minor, 128, 48);
    const RowParity sphereParity(sphere.vertices, sphere.triangles, glm::ivec2(-12), glm::ivec2(12));
    const RowParity torusParity(torus.vertices, torus.triangles, glm::ivec2(-12), glm::ivec2(12));
    std::vector<double> xs;
    int insideSphere = 0, insideTorus = 0;
    for (int k = -12; k <= 12; ++k)
        for (int j = -12; j <= 12; ++j) {
            sphereParity.crossings(j, k, xs);
            EXPECT_EQ(xs.size() % 2, 0u);
            for (int i = -12; i <= 12; ++i) {
                const glm::dvec3 p = glm::dvec3(i, j, k) - centre;
                const double signedDistance = glm::length(p) - radius;
                if (std::abs(signedDistance) < 0.05) continue;
                EXPECT_EQ(RowParity::inside(xs, i), signedDistance < 0.0) << i << ", " << j << ", " << k;
                insideSphere += signedDistance < 0.0;
            }
            torusParity.crossings(j, k, xs);
            EXPECT_EQ(xs.size() % 2, 0u);
            for (int i = -12; i <= 12; ++i) {
                const glm::dvec3 p = glm::dvec3(i, j, k) - centre;
                const double signedDistance = std::hypot(std::hypot(p.x, p.z) - major, p.y) - minor;
                if (std::abs(signedDistance) < 0.05) continue;
                EXPECT_EQ(RowParity::inside(xs, i), signedDistance < 0.0) << i << ", " << j << ", " << k;
                insideTorus += signedDistance < 0.0;
            }
        }
    EXPECT_GT(insideSphere, 3000);  // 4/3·π·9.6³ ≈ 3700 lattice points
    EXPECT_GT(insideTorus, 1000);   // 2π²·7·3² ≈ 1240
}

TEST(RowParity, RowsOutsideTheRangeHaveNoCrossings) {
    const TriangleMesh box = boxMesh(glm::dvec3(-10), glm::dvec3(10), glm::ivec3(1));
    const RowParity parity(box.vertices, box.triangles, glm::ivec2(-2), glm::ivec2(2));
    std::vector<double> xs{1.0};
    parity.crossings(3, 0, xs);
    EXPECT_TRUE(xs.empty());
    parity.crossings(2, -2, xs);
    EXPECT_EQ(xs, (std::vector<double>{-10.0, 10.0}));
}

}  // namespace
}  // namespace eikon::sim
