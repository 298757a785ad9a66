// Deformers driven past sense — bent through themselves, handles swapped,
// twisted into knots, shrunk to a point — must leave finite vertices and
// coverage in [0, 1], never NaN, Inf or a crash. Small grids: this test also
// runs under AddressSanitizer and UndefinedBehaviorSanitizer.
#include "sim/deform/ArapDeformer.h"
#include "sim/deform/MeshShapes.h"
#include "sim/deform/SpatialDeformers.h"
#include "sim/voxelize/MeshCoverage.h"

#include <gtest/gtest.h>

#include <cmath>

namespace eikon::sim {
namespace {

const GridSpec kGrid{glm::ivec3(24), glm::dvec3(-1.0), glm::dvec3(1.0)};

TriangleMesh bar() { return boxMesh(glm::dvec3(-0.5, -0.05, -0.05), glm::dvec3(0.5, 0.05, 0.05), glm::ivec3(12, 2, 2)); }

void expectSane(const std::vector<glm::dvec3>& vertices, const TriangleMesh& topology) {
    for (const glm::dvec3& v : vertices) ASSERT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
    TriangleMesh mesh = topology;
    mesh.vertices = vertices;
    MeshCoverage coverage(kGrid);
    coverage.update(mesh);
    for (float c : coverage.values()) ASSERT_TRUE(c >= 0.0f && c <= 1.0f) << c;  // false for NaN
}

TEST(DeformStability, BendFoldedThroughItselfStaysFinite) {
    const TriangleMesh rest = bar();
    DeformerDesc desc;
    desc.axis = glm::dvec3(1, 0, 0);
    desc.toward = glm::dvec3(0, 1, 0);
    desc.amount = {{0.0, 5000.0}};  // radius 1 cm < half thickness: the inner side turns inside out
    BendDeformer bend(desc, rest);
    std::vector<glm::dvec3> out;
    bend.deform(0.0, out);
    expectSane(out, rest);
}

TEST(DeformStability, TwistIntoAKnotStaysFinite) {
    const TriangleMesh rest = bar();
    DeformerDesc desc;
    desc.axis = glm::dvec3(1, 0, 0);
    desc.amount = {{0.0, 1e6}};
    TwistDeformer twist(desc, rest);
    std::vector<glm::dvec3> out;
    twist.deform(0.0, out);
    expectSane(out, rest);
}

TEST(DeformStability, RigidCollapseToAPointStaysFinite) {
    const TriangleMesh rest = bar();
    DeformerDesc desc;
    desc.keys = {{0.0, {glm::dvec3(0.0), glm::dvec3(0.0), 1e-12}}};
    RigidDeformer rigid(desc, rest);
    std::vector<glm::dvec3> out;
    rigid.deform(0.0, out);
    expectSane(out, rest);
}

// The two end handles swap places and turn over: every triangle between
// them must invert.
TEST(DeformStability, ArapWithCrossedHandlesStaysFinite) {
    const TriangleMesh rest = bar();
    DeformerDesc desc;
    desc.iterations = 5;
    desc.handles.push_back({glm::dvec3(-1), glm::dvec3(-0.45, 1, 1), {{0.0, {glm::dvec3(0.0), glm::dvec3(0.0), 1.0}},
                                                                      {1.0, {glm::dvec3(1.0, 0, 0), glm::dvec3(180, 0, 0), 1.0}}}});
    desc.handles.push_back({glm::dvec3(0.45, -1, -1), glm::dvec3(1), {{0.0, {glm::dvec3(0.0), glm::dvec3(0.0), 1.0}},
                                                                     {1.0, {glm::dvec3(-1.0, 0, 0), glm::dvec3(0, 0, 180), 1.0}}}});
    ArapDeformer arap(desc, rest, "objects[0].deformer");
    std::vector<glm::dvec3> out;
    for (double t : {0.5, 1.0}) {
        arap.deform(t, out);
        expectSane(out, rest);
    }
}

}  // namespace
}  // namespace eikon::sim
