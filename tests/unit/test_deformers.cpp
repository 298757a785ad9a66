// Deformers against closed forms: ARAP bending a bar by its end handles
// (edge lengths and volume), twist and bend maps, keyed rigid poses.
#include "bridge/core/Error.h"
#include "sim/deform/ArapDeformer.h"
#include "sim/deform/Keyframes.h"
#include "sim/deform/MeshShapes.h"
#include "sim/deform/SpatialDeformers.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <numbers>

namespace eikon::sim {
namespace {

// A 1 m bar along x with a 0.1 m square section, and a slender one (0.06 m).
TriangleMesh bar() { return boxMesh(glm::dvec3(0, -0.05, -0.05), glm::dvec3(1, 0.05, 0.05), glm::ivec3(40, 4, 4)); }
TriangleMesh slenderBar() { return boxMesh(glm::dvec3(0, -0.03, -0.03), glm::dvec3(1, 0.03, 0.03), glm::ivec3(50, 3, 3)); }

double maxRelativeEdgeChange(const TriangleMesh& rest, const std::vector<glm::dvec3>& deformed) {
    double worst = 0.0;
    for (const glm::ivec3& t : rest.triangles)
        for (int c = 0; c < 3; ++c) {
            const int a = t[c], b = t[(c + 1) % 3];
            const double before = glm::distance(rest.vertices[a], rest.vertices[b]);
            const double after = glm::distance(deformed[a], deformed[b]);
            worst = std::max(worst, std::abs(after / before - 1.0));
        }
    return worst;
}

PoseKey key(double time, glm::dvec3 translate, glm::dvec3 rotateDeg) { return {time, {translate, rotateDeg, 1.0}}; }

// The right end is carried to where an arc-length-preserving bend of 60°
// would put it; ARAP must find a bent bar whose edges keep their lengths
// within 5% and whose volume stays within 3% (acceptance of issue 6). Any
// bend stretches the outer fibres by (half thickness)·κ — 3.1% here, which
// is why the bar is slender: a 0.1 m section would need 5.2%.
TEST(ArapDeformer, BarBentByItsEndHandlesKeepsEdgesAndVolume) {
    const TriangleMesh rest = slenderBar();
    const double radius = 1.0 / (std::numbers::pi / 3.0);  // arc of 60° over 1 m
    const double s = 0.98, phi = s / radius;              // centroid of the right handle's vertices
    const glm::dvec3 arcPoint(radius * std::sin(phi), radius * (1.0 - std::cos(phi)), 0.0);
    DeformerDesc desc;
    desc.kind = DeformerDesc::Kind::Arap;
    desc.iterations = 30;
    desc.handles.push_back({glm::dvec3(-1, -1, -1), glm::dvec3(0.041, 1, 1), {}});
    desc.handles.push_back({glm::dvec3(0.959, -1, -1), glm::dvec3(2, 1, 1),
                            {key(0.0, glm::dvec3(0), glm::dvec3(0)),
                             key(1.0, arcPoint - glm::dvec3(s, 0, 0), glm::dvec3(0, 0, glm::degrees(phi)))}});
    ArapDeformer arap(desc, rest, "objects[0].deformer");
    EXPECT_GT(arap.handleVertexCount(), 20u);
    std::vector<glm::dvec3> deformed;
    for (double t : {0.25, 0.5, 0.75, 1.0}) arap.deform(t, deformed);  // frames, warm-started

    TriangleMesh bent = rest;
    bent.vertices = deformed;
    const double edgeError = maxRelativeEdgeChange(rest, deformed);
    const double volumeError = enclosedVolume(bent) / enclosedVolume(rest) - 1.0;
    RecordProperty("arap_max_edge_error", std::to_string(edgeError));
    RecordProperty("arap_volume_error", std::to_string(volumeError));
    EXPECT_LT(edgeError, 0.05);
    EXPECT_NEAR(volumeError, 0.0, 0.03);
    // It did bend: the middle of the bar's axis rose toward the arc's sagitta.
    glm::dvec3 middle(0.0);
    int count = 0;
    for (std::size_t v = 0; v < rest.vertices.size(); ++v)
        if (std::abs(rest.vertices[v].x - 0.5) < 1e-9) {
            middle += deformed[v];
            ++count;
        }
    middle /= count;
    const double expectedRise = radius * (1.0 - std::cos(0.5 / radius));
    EXPECT_NEAR(middle.y, expectedRise, 0.3 * expectedRise);
}

TEST(ArapDeformer, HandleRegionsMustHoldVertices) {
    DeformerDesc desc;
    desc.kind = DeformerDesc::Kind::Arap;
    desc.handles.push_back({glm::dvec3(5), glm::dvec3(6), {}});
    try {
        ArapDeformer(desc, bar(), "objects[2].deformer");
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("objects[2].deformer.handles[0]"), std::string::npos) << error.what();
    }
}

// Twist: a vertex at distance s along the axis turns by τ·s about it.
TEST(SpatialDeformers, TwistTurnsEachSectionByRateTimesDistance) {
    const TriangleMesh rest = bar();
    DeformerDesc desc;
    desc.kind = DeformerDesc::Kind::Twist;
    desc.axis = glm::dvec3(1, 0, 0);
    desc.amount = {{0.0, 0.0}, {2.0, 90.0}};  // 45°/m at t = 1
    TwistDeformer twist(desc, rest);
    std::vector<glm::dvec3> out;
    twist.deform(1.0, out);
    for (std::size_t v = 0; v < rest.vertices.size(); ++v) {
        const glm::dvec3 p = rest.vertices[v];
        const double angle = glm::radians(45.0) * p.x;
        const glm::dvec3 expected(p.x, p.y * std::cos(angle) - p.z * std::sin(angle), p.y * std::sin(angle) + p.z * std::cos(angle));
        ASSERT_NEAR(glm::distance(out[v], expected), 0.0, 1e-12);
    }
}

// Bend: the axis becomes an arc of radius 1/κ; for a section symmetric about
// the axis the volume is preserved (the Jacobian is 1 − u·κ, odd in u).
TEST(SpatialDeformers, BendPutsTheAxisOnAnArcAndKeepsVolume) {
    const TriangleMesh rest = bar();
    DeformerDesc desc;
    desc.kind = DeformerDesc::Kind::Bend;
    desc.axis = glm::dvec3(1, 0, 0);
    desc.toward = glm::dvec3(0, 1, 0);
    desc.amount = {{0.0, 90.0}};  // 90° per metre
    BendDeformer bend(desc, rest);
    TriangleMesh bent = rest;
    bend.deform(0.0, bent.vertices);
    const double radius = 1.0 / glm::radians(90.0);
    for (std::size_t v = 0; v < rest.vertices.size(); ++v) {
        const glm::dvec3 p = rest.vertices[v];
        if (p.y != 0.0 || p.z != 0.0) continue;  // vertices on the axis: none on this bar's surface
        ASSERT_NEAR(glm::distance(bent.vertices[v], glm::dvec3(radius * std::sin(p.x / radius), radius * (1 - std::cos(p.x / radius)), 0)), 0.0, 1e-12);
    }
    const glm::dvec3 end = bent.vertices[rest.vertices.size() - 1];
    EXPECT_GT(end.y, 0.0) << "it bends toward +y";
    EXPECT_NEAR(enclosedVolume(bent) / enclosedVolume(rest), 1.0, 0.005);
    // Fibres at distance u from the axis stretch by u·κ: at most 0.05·π/2 on the surface.
    EXPECT_LT(maxRelativeEdgeChange(rest, bent.vertices), 0.05 * glm::radians(90.0) + 1e-3);
}

TEST(SpatialDeformers, RigidPoseInterpolatesBetweenKeysAndHoldsOutside) {
    const TriangleMesh rest = bar();
    DeformerDesc desc;
    desc.kind = DeformerDesc::Kind::Rigid;
    desc.keys = {key(1.0, glm::dvec3(0), glm::dvec3(0)), key(3.0, glm::dvec3(0.4, 0, 0), glm::dvec3(0, 90, 0))};
    RigidDeformer rigid(desc, rest);
    std::vector<glm::dvec3> out;
    rigid.deform(0.0, out);
    for (std::size_t v = 0; v < out.size(); ++v)
        ASSERT_NEAR(glm::distance(out[v], rest.vertices[v]), 0.0, 1e-15) << "held at the first key before it";
    rigid.deform(2.0, out);
    TriangleMesh moved = rest;
    moved.vertices = out;
    EXPECT_NEAR(enclosedVolume(moved), enclosedVolume(rest), 1e-12);
    EXPECT_NEAR(maxRelativeEdgeChange(rest, out), 0.0, 1e-12);
    glm::dvec3 lo, hi;
    vertexBounds(moved, lo, hi);
    EXPECT_NEAR(0.5 * (lo.x + hi.x), 0.5 + 0.2, 1e-12) << "half the translation at the middle time";
    EXPECT_NEAR(hi.z - lo.z, std::sqrt(0.5) * 1.1, 1e-9) << "turned by 45° about y";
}

}  // namespace
}  // namespace eikon::sim
