// Sharp mesh surfaces against the analytic sphere: a latitude–longitude
// sphere mesh's triangles are found by the photon pass in their tree
// (shaders/common/sharp_triangle_surfaces.glsl). From recorded photon paths
// (a vertex is recorded where a step ends on a surface), with Fresnel
// reflection off and a uniform medium so that only the surface turns a
// photon: the surface-position error |x − c| − R of each crossing, and the
// normal error — Snell's law in vector form makes n₁·d_in − n₂·d_out
// parallel to the normal the tracer used — against the sphere's normal
// (x − c)/R. A crossing lies on a facet, so its position error is the
// facets' sag, whatever the grid; the normal is the corners' interpolated,
// whose error on a sphere is second order in the facets' angle.
#include "sim/SceneFields.h"
#include "sim/deform/MeshShapes.h"
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace eikon::test {
namespace {

constexpr double kRadius = 0.25;
constexpr double kIndex = 1.5;

// The deepest a sphere mesh's facets sag below the sphere: R less the
// least distance of a facet's plane from the centre.
double largestSag(const TriangleMesh& mesh) {
    double sag = 0.0;
    for (const glm::ivec3& t : mesh.triangles) {
        const glm::dvec3 &a = mesh.vertices[t.x], &b = mesh.vertices[t.y], &c = mesh.vertices[t.z];
        const glm::dvec3 n = glm::normalize(glm::cross(b - a, c - a));
        sag = std::max(sag, kRadius - std::abs(glm::dot(a, n)));
    }
    return sag;
}

struct SurfaceErrors {
    int crossings = 0;
    double rmsPosition = 0.0, maxPosition = 0.0;  // m
    double rmsNormal = 0.0, maxNormal = 0.0;      // degrees
};

SurfaceErrors sphereMeshErrors(int gridResolution, int rings, const std::string& name) {
    Scene scene = emptyScene(glm::dvec3(-0.5), glm::dvec3(0.5), gridResolution);
    ObjectDesc ball = meshObject(sim::sphereMesh(glm::dvec3(0.0), kRadius, rings, 2 * rings), name, kIndex);
    ball.fresnel = false;
    scene.objects.push_back(ball);
    scene.lights.push_back(directionalLight({0.1, -1.0, 0.05}, 1.0));
    scene.render.photons = 1 << 16;
    const int recorded = 4096, perPhoton = 16;
    const sim::SceneFields fields(scene);
    const TraceResult result =
        traceFields(scene, fields.fields(), {.recordPathVertices = perPhoton, .recordedPhotons = recorded, .recordStride = 13});
    SurfaceErrors errors;
    double positionSquares = 0.0, normalSquares = 0.0;
    for (int photon = 0; photon < recorded; ++photon) {
        std::vector<glm::dvec3> path;
        for (int v = 0; v < perPhoton; ++v) {
            const glm::vec4& vertex = result.paths[static_cast<std::size_t>(photon * perPhoton + v)];
            if (vertex.w != 1.0f) break;
            path.emplace_back(vertex);
        }
        for (std::size_t v = 1; v + 1 < path.size(); ++v) {
            // A crossing: a turn by more than 1e-3 rad within R/10 of the sphere.
            const double position = std::abs(glm::length(path[v]) - kRadius);
            if (position > 0.1 * kRadius) continue;
            const glm::dvec3 in = glm::normalize(path[v] - path[v - 1]);
            const glm::dvec3 out = glm::normalize(path[v + 1] - path[v]);
            if (glm::dot(in, out) > std::cos(1e-3)) continue;
            const bool before = glm::length(path[v - 1]) > kRadius, after = glm::length(path[v + 1]) > kRadius;
            if (before == after) continue;  // a total internal reflection, which Snell's law does not describe
            const bool entering = before;
            const double n1 = entering ? 1.0 : kIndex, n2 = entering ? kIndex : 1.0;
            const glm::dvec3 used = glm::normalize(n1 * in - n2 * out);
            const glm::dvec3 exact = glm::normalize(path[v]);
            const double normal = std::acos(std::min(1.0, std::abs(glm::dot(used, exact)))) * 180.0 / M_PI;
            positionSquares += position * position;
            normalSquares += normal * normal;
            errors.maxPosition = std::max(errors.maxPosition, position);
            errors.maxNormal = std::max(errors.maxNormal, normal);
            ++errors.crossings;
        }
    }
    errors.rmsPosition = std::sqrt(positionSquares / std::max(errors.crossings, 1));
    errors.rmsNormal = std::sqrt(normalSquares / std::max(errors.crossings, 1));
    return errors;
}

void report(const std::string& label, const SurfaceErrors& errors) {
    reportFigure(("sharp_mesh_" + label + "_rms_position_error_m").c_str(), errors.rmsPosition);
    reportFigure(("sharp_mesh_" + label + "_max_position_error_m").c_str(), errors.maxPosition);
    reportFigure(("sharp_mesh_" + label + "_rms_normal_error_deg").c_str(), errors.rmsNormal);
    reportFigure(("sharp_mesh_" + label + "_max_normal_error_deg").c_str(), errors.maxNormal);
}

// A fine mesh (96 rings, 36 864 triangles: facets 1.9° apart, sagging up
// to 67 µm at their centres) on grids of h = 1/64 m and 1/128 m: the grid
// plays no part. A coarse mesh (24 rings, facets 7.5° apart) sags 16 times
// deeper; its interpolated normals stay within a fraction of a degree,
// except where a grazing ray would refract to the wrong side of its facet
// about them and takes the facet's own normal instead.
TEST(SharpMesh, SphereMeshCrossingsLieOnTheFacetsWithTheSpheresNormals) {
    const TriangleMesh fineMesh = sim::sphereMesh(glm::dvec3(0.0), kRadius, 96, 192);
    const SurfaceErrors coarse = sphereMeshErrors(64, 96, "sphere96.obj");
    const SurfaceErrors fine = sphereMeshErrors(128, 96, "sphere96.obj");
    report("h64", coarse);
    report("h128", fine);
    ASSERT_GE(coarse.crossings, 500);
    ASSERT_GE(fine.crossings, 500);
    const double sag = largestSag(fineMesh);
    reportFigure("sharp_mesh_96_rings_largest_sag_m", sag);
    EXPECT_LE(coarse.maxPosition, sag * (1.0 + 1e-3) + 1e-6) << "on the facets (1 µm of float)";
    EXPECT_LE(coarse.rmsPosition, 0.6 * sag);
    EXPECT_NEAR(fine.rmsPosition, coarse.rmsPosition, 0.05 * coarse.rmsPosition) << "the grid plays no part";
    EXPECT_LE(coarse.rmsNormal, 0.02);
    EXPECT_LE(coarse.maxNormal, 0.05);
    EXPECT_LE(fine.maxNormal, 0.05);
    const SurfaceErrors faceted = sphereMeshErrors(64, 24, "sphere24.obj");
    report("h64_rings24", faceted);
    ASSERT_GE(faceted.crossings, 500);
    const double coarseSag = largestSag(sim::sphereMesh(glm::dvec3(0.0), kRadius, 24, 48));
    EXPECT_LE(faceted.maxPosition, coarseSag * (1.0 + 1e-3) + 1e-6);
    EXPECT_GT(faceted.rmsPosition, coarse.rmsPosition);
    EXPECT_LE(faceted.rmsNormal, 0.5);
}

}  // namespace
}  // namespace eikon::test
