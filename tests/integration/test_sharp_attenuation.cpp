// A sharp absorbing sphere attenuates light between its exact surface
// crossings, not between voxel faces: the camera's transmittance per pixel
// and each photon's power across the sphere against Beer–Lambert over the
// refracted chord, exp(−κ·ℓ) ([Ihrke07] §3, eq. 5). The sphere's extinction
// is voxelised (a 24³ grid, voxels a tenth of the sphere's diameter); read
// where the ray is, the voxels its surface cuts blend glass and air, and the
// transmittance near the silhouette is off by up to a voxel's worth of
// absorption.
#include "render/graph/FrameRenderer.h"
#include "sim/voxelize/AnalyticVoxelizer.h"
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"
#include "verify/reference/PinholeCamera.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace eikon::test {
namespace {

constexpr double kRadius = 0.2, kIndex = 1.5, kExtinction = 5.0;  // κ·2R = 2: e^−2 through the centre
constexpr double kVoxel = 0.6 / 24;

// A glass ball of extinction κ, centred in a 24³ grid of [−0.3, 0.3]³, no
// Fresnel reflection (all of a ray goes on refracted; a sphere never
// reflects totally from inside what entered it).
Scene absorbingSphereScene() {
    Scene scene = emptyScene(glm::dvec3(-0.3), glm::dvec3(0.3), 24);
    ObjectDesc ball;
    ball.kind = ObjectDesc::Kind::Sphere;
    ball.sphere = {glm::dvec3(0.0), kRadius};
    ball.material.index = kIndex;
    ball.material.extinction = Rgb(kExtinction);
    ball.fresnel = false;
    scene.objects.push_back(ball);
    return scene;
}

// The length of the refracted chord through the sphere of a straight ray
// passing the centre at distance b < R: it enters at θi = asin(b/R), is bent
// to θt = asin(sin θi / n), and crosses 2R·cos θt.
double refractedChord(double b) {
    const double sinT = b / kRadius / kIndex;
    return 2.0 * kRadius * std::sqrt(1.0 - sinT * sinT);
}

struct ErrorBand {
    double sumSquares = 0.0;
    int count = 0;
    void add(double error) {
        sumSquares += error * error;
        ++count;
    }
    double rms() const { return count > 0 ? std::sqrt(sumSquares / count) : 0.0; }
};

// The camera looks at the ball against a uniform environment of radiance 1,
// one ray a pixel through its centre: each pixel's radiance is the ray's
// transmittance, exp(−κ·chord(b)) where its impact parameter b < R and 1
// beside the ball. The pixels whose ray passes within two voxels of the
// silhouette (b in R ± 2h) are the rim, those further in the interior; the
// rim's RMS error must be as small as the interior's.
TEST(SharpAttenuation, CameraSeesBeerLambertOverTheRefractedChord) {
    Scene scene = absorbingSphereScene();
    scene.lights.push_back(directionalLight({0.0, -1.0, 0.0}, 1.0));
    scene.render.photons = 64;
    scene.render.width = 81;
    scene.render.height = 81;
    scene.render.samplesPerPixel = 1;
    scene.render.environment.radiance = Rgb(1.0);
    scene.camera.position = glm::dvec3(0.0, 0.0, 3.0);
    scene.camera.target = glm::dvec3(0.0);
    scene.camera.fovDeg = 9.0;  // the ball, 7.6° across, fills most of the image
    glContext();
    const FieldSet fields = sim::voxelizeScene(scene);
    render::FrameRenderer renderer(scene, fields, {.photons = {}});
    renderer.render(fields);
    const std::vector<float> hdr = renderer.viewStage().downloadHdr();

    ErrorBand rim, interior, outside;
    for (int j = 0; j < scene.render.height; ++j)
        for (int i = 0; i < scene.render.width; ++i) {
            const glm::dvec3 d = reference::pixelDirection(scene.camera, scene.render.width, scene.render.height, i, j);
            const glm::dvec3 toCentre = -scene.camera.position;
            const double b = glm::length(toCentre - glm::dot(toCentre, d) * d);
            const double expected = b < kRadius ? std::exp(-kExtinction * refractedChord(b)) : 1.0;
            const std::size_t pixel = 4 * static_cast<std::size_t>(j * scene.render.width + i);
            for (int channel = 0; channel < 3; ++channel) {
                const double error = hdr[pixel + channel] - expected;
                if (std::abs(b - kRadius) < 2.0 * kVoxel) rim.add(error);
                else if (b < kRadius) interior.add(error);
                else outside.add(error);
            }
        }
    reportFigure("sharp_absorber_view_rim_rms_error", rim.rms());
    reportFigure("sharp_absorber_view_interior_rms_error", interior.rms());
    reportFigure("sharp_absorber_view_outside_rms_error", outside.rms());
    EXPECT_GT(rim.count, 3 * 300);
    EXPECT_GT(interior.count, 3 * 1000);
    EXPECT_LT(rim.rms(), 1e-4) << "the silhouette is drawn at the surface, not at voxel faces";
    EXPECT_LT(interior.rms(), 1e-4);
    EXPECT_LT(outside.rms(), 1e-4) << "nothing absorbs beside the ball";
}

// Parallel light falls on the ball; every photon that crosses it is
// recorded at each step. Between the vertex where it enters (on the
// surface) and the one where it leaves, its power must fall by
// exp(−κ·ℓ), ℓ the distance between them, and ℓ must be the refracted
// chord of its impact parameter. The energy ledger closes (traceFields).
TEST(SharpAttenuation, PhotonsLosePowerOverTheRefractedChord) {
    Scene scene = absorbingSphereScene();
    scene.lights.push_back(directionalLight({0.0, -1.0, 0.0}, 1.0));
    scene.render.photons = 1 << 14;
    const int recorded = 256, perPhoton = 64;
    const TraceResult result = trace(scene, {.recordPathVertices = perPhoton, .recordedPhotons = recorded, .recordStride = 61});
    ErrorBand transmittance;
    double worstChord = 0.0, outermost = 0.0;
    for (int photon = 0; photon < recorded; ++photon) {
        std::vector<int> onSurface;
        for (int v = 0; v < perPhoton; ++v) {
            const std::size_t at = static_cast<std::size_t>(photon * perPhoton + v);
            if (result.paths[at].w != 1.0f) break;
            if (std::abs(glm::length(glm::dvec3(result.paths[at])) - kRadius) < 1e-5) onSurface.push_back(v);
        }
        if (onSurface.size() < 2) continue;
        const std::size_t in = static_cast<std::size_t>(photon * perPhoton + onSurface[0]);
        const std::size_t out = static_cast<std::size_t>(photon * perPhoton + onSurface[1]);
        const glm::dvec3 entry(result.paths[in]);
        const double b = std::hypot(entry.x, entry.z);  // the light falls along −y
        const double chord = glm::distance(entry, glm::dvec3(result.paths[out]));
        worstChord = std::max(worstChord, std::abs(chord - refractedChord(b)));
        outermost = std::max(outermost, b);
        for (int channel = 0; channel < 3; ++channel) {
            const double measured = result.pathPower[out][channel] / result.pathPower[in][channel];
            transmittance.add(measured - std::exp(-kExtinction * chord));
        }
    }
    reportFigure("sharp_absorber_photon_transmittance_rms_error", transmittance.rms());
    reportFigure("sharp_absorber_photon_chord_worst_error_m", worstChord);
    EXPECT_GE(transmittance.count, 3 * 40);
    EXPECT_GT(outermost, kRadius - kVoxel) << "some photons cross the ball within a voxel of its rim";
    EXPECT_LT(worstChord, 1e-5);
    EXPECT_LT(transmittance.rms(), 1e-4);
}

}  // namespace
}  // namespace eikon::test
