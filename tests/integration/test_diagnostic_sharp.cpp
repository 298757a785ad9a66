// The diagnostics through sharp surfaces (docs/scene-format.md,
// `diagnostic`; docs/accuracy.md, "Diagnostics") against the exact optics
// of a glass sphere in double precision (verify/reference/SphereOptics.h,
// which shares no code with the renderer). Parallel light along −z crosses
// a sphere of index n in air: a ray at impact parameter ρ refracts in,
// crosses the chord 2·√(R² − (ρ/n)²) and refracts out, so that
// OPD = (n − 1)·chord and its deflection is the angle between its exit
// direction and −z, along the direction its part across the beam points. A
// ray turned by 90° or more is lost (it never reaches the instrument).
// The shadowgraph and BOS follow the same exact rays on to the screen or
// background. The graded field is uniform (δn = 0).
#include "render/graph/FrameRenderer.h"
#include "sim/SceneFields.h"
#include "sim/deform/MeshShapes.h"
#include "tests/integration/GaussianBump.h"
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"
#include "verify/reference/SphereOptics.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

namespace eikon {
namespace {

using namespace test;

constexpr float kCrossed = 1.0f;
constexpr float kLost = 3.0f;

// One ray a pixel through its centre; a glass sphere at the origin.
Scene sphereScene(int size, const DiagnosticDesc& diagnostic, double radius, double index) {
    Scene scene = bumpScene(size, size, diagnostic);
    scene.render.samplesPerPixel = 1;
    ObjectDesc sphere;
    sphere.sphere = {glm::dvec3(0.0), radius};
    sphere.material.index = index;
    scene.objects.push_back(sphere);
    return scene;
}

render::DiagnosticMeasurements measure(const Scene& scene, std::vector<glm::vec4>* rays = nullptr,
                                       std::vector<float>* hdr = nullptr) {
    glContext();
    const sim::SceneFields fields(scene);
    render::FrameRenderer renderer(scene, fields.fields());
    renderer.render(fields.fields());
    if (rays) *rays = renderer.diagnosticStage()->downloadRays();
    if (hdr) *hdr = renderer.diagnosticStage()->downloadHdr();
    return renderer.diagnosticStage()->downloadMeasurements();
}

// The exact ray through pixel point p: OPD (m), deflection on the image's
// right and up axes (rad), and whether it is lost; nullopt where it misses.
struct ExactRay {
    double opd;
    glm::dvec2 deflection;
    bool lost;
};

std::optional<ExactRay> exactRay(glm::dvec2 p, double radius, double index) {
    const reference::Sphere sphere{glm::dvec3(0.0), radius};
    const glm::dvec3 origin(p, 1.0), down(0.0, 0.0, -1.0);
    const auto transit = reference::transitSphere(origin, down, sphere, index);
    if (!transit) return std::nullopt;
    const glm::dvec3 entry = origin + reference::sphereHit(origin, down, sphere, 0.0) * down;
    const glm::dvec3 out = transit->exitDirection;
    const double across = std::hypot(out.x, out.y);
    const double angle = std::atan2(across, -out.z);
    const glm::dvec2 deflection = across > 0.0 ? angle / across * glm::dvec2(out.x, out.y) : glm::dvec2(0.0);
    return ExactRay{(index - 1.0) * glm::length(transit->exitPoint - entry), deflection, out.z >= 0.0};
}

struct SphereMapErrors {
    double opdRms = 0.0, opdWorst = 0.0;                // of the peak OPD
    double deflectionRms = 0.0, deflectionWorst = 0.0;  // of the peak deflection
    int lost = 0, expectedLost = 0, wrongEnding = 0;
};

SphereMapErrors sphereMapErrors(const Scene& scene, const render::DiagnosticMeasurements& measured,
                                const std::vector<glm::vec4>& rays, double radius, double index) {
    SphereMapErrors errors;
    const int size = scene.render.width;
    const double peakOpd = (index - 1.0) * 2.0 * radius;
    double peakDeflection = 0.0;
    std::vector<std::optional<ExactRay>> exact;
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            exact.push_back(exactRay(pixelPoint(scene, i, j), radius, index));
            if (exact.back()) peakDeflection = std::max(peakDeflection, glm::length(exact.back()->deflection));
        }
    for (std::size_t k = 0; k < exact.size(); ++k) {
        const ExactRay ray = exact[k].value_or(ExactRay{0.0, glm::dvec2(0.0), false});
        const float ending = rays[k].w;
        errors.lost += ending == kLost;
        errors.expectedLost += ray.lost;
        errors.wrongEnding += ending != (ray.lost ? kLost : kCrossed);
        const double opd = std::abs(measured.opticalPathDifference[k] - ray.opd) / peakOpd;
        const glm::dvec2 found(measured.deflection[2 * k], measured.deflection[2 * k + 1]);
        const double deflection = glm::length(found - ray.deflection) / peakDeflection;
        errors.opdRms += opd * opd;
        errors.deflectionRms += deflection * deflection;
        errors.opdWorst = std::max(errors.opdWorst, opd);
        errors.deflectionWorst = std::max(errors.deflectionWorst, deflection);
    }
    errors.opdRms = std::sqrt(errors.opdRms / static_cast<double>(exact.size()));
    errors.deflectionRms = std::sqrt(errors.deflectionRms / static_cast<double>(exact.size()));
    return errors;
}

constexpr double kRadius = 0.3;
constexpr double kGlass = 1.9;  // dense flint

// A glass sphere (n = 1.9, R = 0.3 m) in the interferometer, 96 × 96
// pixels over 0.8 m: OPD and deflection per pixel against the exact ray.
// Rays beyond ρ/R = 0.969 leave turned by more than 90° (2·(θᵢ − θₜ) ≥
// π/2; for n = 1.5 only beyond 0.998): they are lost, and the
// interferometer shows the reference beam alone there (I/I₀ = 1/4).
TEST(DiagnosticSharp, OpticalPathAndDeflectionThroughAGlassSphereAreTheExactRays) {
    const Scene scene = sphereScene(96, DiagnosticDesc{}, kRadius, kGlass);
    std::vector<glm::vec4> rays;
    std::vector<float> hdr;
    const render::DiagnosticMeasurements measured = measure(scene, &rays, &hdr);
    const SphereMapErrors errors = sphereMapErrors(scene, measured, rays, kRadius, kGlass);
    reportFigure("sharp_sphere_opd_rms_error_of_peak", errors.opdRms);
    reportFigure("sharp_sphere_opd_worst_error_of_peak", errors.opdWorst);
    reportFigure("sharp_sphere_deflection_rms_error_of_peak", errors.deflectionRms);
    reportFigure("sharp_sphere_deflection_worst_error_of_peak", errors.deflectionWorst);
    reportFigure("sharp_sphere_lost_pixels", errors.lost);
    EXPECT_LE(errors.opdRms, 0.005);
    EXPECT_LE(errors.deflectionWorst, 0.01);
    EXPECT_GT(errors.expectedLost, 0) << "the rim turns rays back";
    EXPECT_EQ(errors.wrongEnding, 0) << errors.lost << " lost, " << errors.expectedLost << " expected";
    for (std::size_t k = 0; k < rays.size(); ++k) {
        if (rays[k].w == kLost) {
            EXPECT_EQ(hdr[4 * k], 0.25f) << "pixel " << k;
        }
    }
}

// The same sphere as a triangle mesh of 96 rings and 192 segments: its
// facets lie inside the sphere by at most the sagitta s = R·(1 − cos(π/96))
// ≈ 1.6e-4 m, so the chord differs by at most 2s/cos θₜ, OPD by (n − 1)
// times that; the normals are the
// corners' interpolated. Its maps equal the analytic sphere's within that
// bound (OPD) and 1% of the peak (deflection); the rim, where a ray grazes
// a facet and the mesh's outline is a polygon, is left out (ρ > 0.95 R).
TEST(DiagnosticSharp, ASphereMeshGivesTheAnalyticSpheresMapsWithinItsFaceting) {
    const Scene analytic = sphereScene(96, DiagnosticDesc{}, kRadius, kGlass);
    Scene meshed = analytic;
    meshed.objects[0] =
        meshObject(sim::sphereMesh(glm::dvec3(0.0), kRadius, 96, 192), "diagnostic_sphere96.obj", kGlass);
    const render::DiagnosticMeasurements exact = measure(analytic), faceted = measure(meshed);
    const double peakOpd = (kGlass - 1.0) * 2.0 * kRadius;
    double peakDeflection = 0.0;
    for (std::size_t k = 0; k < exact.opticalPathDifference.size(); ++k)
        peakDeflection = std::max(peakDeflection, static_cast<double>(std::hypot(exact.deflection[2 * k],
                                                                                 exact.deflection[2 * k + 1])));
    double opdWorst = 0.0, deflectionSquares = 0.0;
    int compared = 0;
    for (int j = 0; j < 96; ++j)
        for (int i = 0; i < 96; ++i) {
            if (glm::length(pixelPoint(analytic, i, j)) > 0.95 * kRadius) continue;
            const std::size_t k = static_cast<std::size_t>(j * 96 + i);
            opdWorst = std::max(opdWorst, std::abs(faceted.opticalPathDifference[k] - exact.opticalPathDifference[k]) /
                                              peakOpd);
            const double dx = faceted.deflection[2 * k] - exact.deflection[2 * k];
            const double dy = faceted.deflection[2 * k + 1] - exact.deflection[2 * k + 1];
            deflectionSquares += (dx * dx + dy * dy) / (peakDeflection * peakDeflection);
            ++compared;
        }
    const double deflectionRms = std::sqrt(deflectionSquares / compared);
    reportFigure("sharp_sphere_mesh_opd_worst_of_peak", opdWorst);
    reportFigure("sharp_sphere_mesh_deflection_rms_of_peak", deflectionRms);
    const double sagitta = kRadius * (1.0 - std::cos(std::numbers::pi / 96.0));
    const double steepest = std::sqrt(1.0 - (0.95 / kGlass) * (0.95 / kGlass));  // cos θₜ within ρ ≤ 0.95 R
    EXPECT_LE(opdWorst, (kGlass - 1.0) * 2.0 * sagitta / steepest / peakOpd);
    EXPECT_LE(deflectionRms, 0.01);
}

// A weak glass sphere, n = 1.02, R = 0.25 m (a ball lens of paraxial focal
// length nR/(2(n − 1)) = 6.4 m from its centre), on a shadowgraph screen
// 2 m behind its centre: its spherical aberration has brought the outer
// rays across the axis already while the inner ones still converge, and
// the map from impact parameter to the screen folds where its landing
// point r(ρ) is largest — a ring caustic, of radius 0.0998 m (16.1
// pixels) by the exact rays. Along the row through the axis the light
// falls steeply just outside the ring: the steepest fall beyond 4 pixels
// from the axis is from the pixel that holds the fold to the next.
TEST(DiagnosticSharp, AWeakGlassSpheresShadowgraphCastsItsCausticWhereTheExactRaysFold) {
    constexpr int kSize = 129;  // the middle pixel's centre on the axis
    constexpr double kWeakRadius = 0.25, kWeakGlass = 1.02, kScreen = 1.5;  // the screen 2 m below the centre
    DiagnosticDesc shadowgraph;
    shadowgraph.type = DiagnosticDesc::Type::Shadowgraph;
    shadowgraph.screenDistance = kScreen;
    const Scene scene = sphereScene(kSize, shadowgraph, kWeakRadius, kWeakGlass);
    const reference::Sphere sphere{glm::dvec3(0.0), kWeakRadius};
    const double screenZ = -0.5 - kScreen;
    double ring = 0.0;
    for (int k = 1; k < 20000; ++k) {
        const auto transit = reference::transitSphere(glm::dvec3(kWeakRadius * k / 20000.0, 0.0, 1.0),
                                                      glm::dvec3(0.0, 0.0, -1.0), sphere, kWeakGlass);
        const double t = (screenZ - transit->exitPoint.z) / transit->exitDirection.z;
        ring = std::max(ring, transit->exitPoint.x + t * transit->exitDirection.x);
    }
    const double pixel = kBumpViewWidth / kSize, expected = ring / pixel;
    reportFigure("sharp_sphere_caustic_radius_pixels", expected);
    std::vector<float> hdr;
    measure(scene, nullptr, &hdr);
    const int row = kSize / 2;
    const auto at = [&](int offset) { return hdr[4 * static_cast<std::size_t>(row * kSize + row + offset)]; };
    for (const int side : {-1, 1}) {
        int fold = 4;
        for (int k = 4; k < row; ++k)
            if (at(side * k) - at(side * (k + 1)) > at(side * fold) - at(side * (fold + 1))) fold = k;
        reportFigure(side < 0 ? "sharp_sphere_caustic_left_pixels_off" : "sharp_sphere_caustic_right_pixels_off",
                     fold - expected);
        EXPECT_LE(std::abs(fold - expected), 1.0) << "side " << side;
        EXPECT_GT(at(side * fold), 2.0f * at(side * (fold + 1))) << "side " << side;
    }
}

// Background-oriented schlieren through a weak glass sphere (n = 1.05,
// R = 0.2 m): a pinhole 2 m from its centre (tan of the half view 0.2, 96
// rows), the background 2 m beyond it. Each exact ray from the pinhole
// through a pixel's centre refracts through the sphere and lands on the
// background; the displacement is that pixel less the one whose straight
// ray sees the landing point, in pixels on the image's right and up.
TEST(DiagnosticSharp, BosThroughAGlassSphereDisplacesTheBackgroundAsTheExactRaysDo) {
    constexpr int kSize = 96;
    constexpr double kCameraZ = 2.0, kBackgroundZ = -2.0, kHalfView = 0.2, kWeakRadius = 0.2, kWeakGlass = 1.05;
    DiagnosticDesc bos;
    bos.type = DiagnosticDesc::Type::Bos;
    bos.backgroundDistance = -0.5 - kBackgroundZ;  // behind the grid's far face
    Scene scene = sphereScene(kSize, bos, kWeakRadius, kWeakGlass);
    scene.camera.projection = CameraDesc::Projection::Perspective;
    scene.camera.fovDeg = glm::degrees(2.0 * std::atan(kHalfView));
    const render::DiagnosticMeasurements measured = measure(scene);
    ASSERT_EQ(measured.displacement.size(), 2u * kSize * kSize);
    const reference::Sphere sphere{glm::dvec3(0.0), kWeakRadius};
    const glm::dvec3 camera(0.0, 0.0, kCameraZ);
    const double pixel = 2.0 * kHalfView / kSize;  // at unit distance
    const double metresPerPixel = (kCameraZ - kBackgroundZ) * pixel;  // on the background
    std::vector<glm::dvec2> expected;
    double peak = 0.0;
    for (int j = 0; j < kSize; ++j)
        for (int i = 0; i < kSize; ++i) {
            const glm::dvec3 d =
                glm::normalize(glm::dvec3((i + 0.5 - 0.5 * kSize) * pixel, (0.5 * kSize - j - 0.5) * pixel, -1.0));
            const glm::dvec3 straight = camera + (kBackgroundZ - camera.z) / d.z * d;
            glm::dvec3 landed = straight;
            if (const auto transit = reference::transitSphere(camera, d, sphere, kWeakGlass)) {
                const glm::dvec3 out = transit->exitDirection;
                landed = transit->exitPoint + (kBackgroundZ - transit->exitPoint.z) / out.z * out;
            }
            expected.push_back(-glm::dvec2(landed - straight) / metresPerPixel);
            peak = std::max(peak, glm::length(expected.back()));
        }
    double squares = 0.0, worst = 0.0;
    for (std::size_t k = 0; k < expected.size(); ++k) {
        const glm::dvec2 found(measured.displacement[2 * k], measured.displacement[2 * k + 1]);
        const double error = glm::length(found - expected[k]) / peak;
        squares += error * error;
        worst = std::max(worst, error);
    }
    const double rms = std::sqrt(squares / static_cast<double>(expected.size()));
    reportFigure("sharp_sphere_bos_peak_displacement_px", peak);
    reportFigure("sharp_sphere_bos_rms_error_of_peak", rms);
    reportFigure("sharp_sphere_bos_worst_error_of_peak", worst);
    EXPECT_LE(worst, 0.01);
}

}  // namespace
}  // namespace eikon
