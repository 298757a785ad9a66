// Sharp mesh surfaces against the analytic sphere: a latitude–longitude
// sphere mesh is found by the photon pass as the zero set of its signed
// distance on the grid (shaders/common/sharp_distance_surfaces.glsl). From
// recorded photon paths (a vertex is recorded where a step ends on a
// surface), with Fresnel reflection off and a uniform medium so that only
// the surface turns a photon: the surface-position error |x − c| − R of each
// crossing, and the normal error — Snell's law in vector form makes
// n₁·d_in − n₂·d_out parallel to the normal the tracer used — against the
// sphere's normal (x − c)/R. The errors are reported at two grid resolutions
// (second order in the cell size h is expected of trilinear φ) and for a
// coarser mesh (its facets, not the grid, then dominate).
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
            // A crossing: a turn by more than 1e-3 rad within R/10 of the
            // sphere (fifty times the errors found), between steps of 5 mm or
            // more. Shorter steps are where a grazing ray's search ran out of
            // probes near the surface: their float vertices turn a straight
            // path by more than that, and the crossings they lead to (a few
            // percent, at grazing incidence) are left out.
            const double position = std::abs(glm::length(path[v]) - kRadius);
            if (position > 0.1 * kRadius) continue;
            if (glm::length(path[v] - path[v - 1]) < 5e-3 || glm::length(path[v + 1] - path[v]) < 5e-3) continue;
            const glm::dvec3 in = glm::normalize(path[v] - path[v - 1]);
            const glm::dvec3 out = glm::normalize(path[v + 1] - path[v]);
            if (glm::dot(in, out) > std::cos(1e-3)) continue;
            const bool entering = glm::length(path[v - 1]) > glm::length(path[v + 1]);
            const double before = entering ? 1.0 : kIndex, after = entering ? kIndex : 1.0;
            const glm::dvec3 used = glm::normalize(before * in - after * out);
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

// A fine mesh (96 rings, 36 864 triangles; its facets sag 34 µm and turn
// 1.9°) on grids of h = 1/64 m and 1/128 m. The position error is φ's own
// (trilinear interpolation of a convex distance puts the zero set inside the
// surface by ~h²/(8R) per axis): second order in h. The normal error does
// not shrink with h here: at h = 1/128 m the cells are as small as the
// facets, and φ begins to show them.
TEST(SharpMesh, SphereMeshCrossingsLieOnTheSphereWithItsNormals) {
    const SurfaceErrors coarse = sphereMeshErrors(64, 96, "sphere96.obj");
    const SurfaceErrors fine = sphereMeshErrors(128, 96, "sphere96.obj");
    report("h64", coarse);
    report("h128", fine);
    ASSERT_GE(coarse.crossings, 500);
    ASSERT_GE(fine.crossings, 500);
    const double h = 1.0 / 64.0;
    EXPECT_LE(coarse.rmsPosition, 0.05 * h);
    EXPECT_LE(coarse.maxPosition, 0.1 * h);
    EXPECT_LE(coarse.rmsNormal, 0.25);
    EXPECT_LE(coarse.maxNormal, 1.0);
    EXPECT_LT(fine.rmsPosition, 0.5 * coarse.rmsPosition) << "halving h must shrink the position error";
    EXPECT_LE(fine.rmsNormal, 0.25);
    EXPECT_LE(fine.maxNormal, 1.0);
    // A coarse mesh (24 rings: facets 7.5° apart, sagging 0.5 mm) lies
    // inside the sphere by its sag; φ on cells half a facet wide smooths the
    // facets' normals out.
    const SurfaceErrors faceted = sphereMeshErrors(64, 24, "sphere24.obj");
    report("h64_rings24", faceted);
    ASSERT_GE(faceted.crossings, 500);
    EXPECT_GT(faceted.rmsPosition, coarse.rmsPosition);
    EXPECT_LE(faceted.rmsNormal, 0.5);
}

}  // namespace
}  // namespace eikon::test
