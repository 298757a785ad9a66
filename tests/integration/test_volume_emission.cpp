// Emission ([Ihrke07] §3, L_e) against closed forms: in the viewing pass a
// glowing absorbing slab, and a blackbody flame imported from an OpenVDB
// file, whose radiance by Kirchhoff's law is B(T)·(1 − e^{−κ·chord}) with B
// from sim/optics/Blackbody (checked against Planck's and Stefan–Boltzmann's
// laws and the Planckian locus in tests/unit/test_blackbody.cpp); as a
// light (volume.emission_lights), a glowing cube's power and the irradiance
// it casts on a floor, against quadratures of the radiometry.
#include "io/scene/SceneParser.h"
#include "render/graph/FrameRenderer.h"
#include "sim/SceneFields.h"
#include "sim/optics/Blackbody.h"
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"
#include "tests/unit/VdbTestFiles.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

namespace eikon {
namespace {

namespace fs = std::filesystem;
using namespace test;

std::vector<float> renderHdr(const Scene& scene, const FieldSet& fields) {
    glContext();
    render::FrameRenderer renderer(scene, fields, {.photons = {}});
    renderer.render(fields);
    return renderer.viewStage().downloadHdr();
}

// A slab |x| < 0.125 m (16 of 32 cells, L = 0.25 m) glows with
// ε = (3, 2, 1) W/(m³·sr) inside a medium of uniform κ = (0, 0.5, 1) /m that
// fills the grid [−0.25, 0.25]³. A camera ray along +x entering the grid at
// x = −0.25 sees, with no background,
//   L = ε · e^{−κ·0.125} · (1 − e^{−κL}) / κ    (ε·L where κ = 0).
// Steps of a quarter voxel: the first-order quadrature of the trilinear
// slab edges costs about κ·Δs/2 < 0.2%; tolerance 0.5%. Without κ, with
// octree steps, ε·L to 0.1%.
TEST(VolumeEmission, AGlowingSlabShowsEmissionOverAbsorption) {
    Scene scene = emptyScene(glm::dvec3(-0.25), glm::dvec3(0.25), 32);
    scene.lights.push_back(directionalLight({0.0, -1.0, 0.0}, 1.0));
    scene.render.width = scene.render.height = 3;
    scene.render.stepVoxels = 0.25;
    scene.render.environment.radiance = Rgb(0.0);
    scene.camera.position = glm::dvec3(-1.0, 0.01, 0.01);
    scene.camera.target = glm::dvec3(0.0, 0.01, 0.01);
    scene.camera.fovDeg = 0.5;
    FieldSet fields;
    fields.grid = scene.grid.spec();
    const std::size_t cells = fields.grid.cellCount();
    fields.deltaIndex.assign(cells, 0.0f);
    fields.extinction.resize(3 * cells);
    fields.emission.assign(3 * cells, 0.0f);
    const glm::dvec3 kappa(0.0, 0.5, 1.0), epsilon(3.0, 2.0, 1.0);
    for (int k = 0; k < 32; ++k)
        for (int j = 0; j < 32; ++j)
            for (int i = 0; i < 32; ++i) {
                const std::size_t c = fields.grid.linearIndex(i, j, k);
                for (int ch = 0; ch < 3; ++ch) {
                    fields.extinction[3 * c + ch] = static_cast<float>(kappa[ch]);
                    if (i >= 8 && i < 24) fields.emission[3 * c + ch] = static_cast<float>(epsilon[ch]);
                }
            }
    fields.indexVersion = fields.extinctionVersion = 1;
    const std::vector<float> hdr = renderHdr(scene, fields);
    const double length = 0.25;
    for (int ch = 0; ch < 3; ++ch) {
        const double expected = kappa[ch] == 0.0 ? epsilon[ch] * length
                                                 : epsilon[ch] * std::exp(-kappa[ch] * 0.125) *
                                                       (1.0 - std::exp(-kappa[ch] * length)) / kappa[ch];
        const double measured = hdr[4 * 4 + ch];
        reportFigure(("glowing_slab_measured_over_closed_form_channel_" + std::to_string(ch)).c_str(), measured / expected);
        EXPECT_NEAR(measured / expected, 1.0, 0.005) << "channel " << ch;
    }
    // Glow in clear air (no extinction field at all): octree nodes around
    // it are not empty, so the camera ray steps through and sees ε·L.
    scene.tracer.stepPolicy = TracerDesc::StepPolicy::Octree;
    fields.extinction.clear();
    const std::vector<float> clear = renderHdr(scene, fields);
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(clear[4 * 4 + ch] / (epsilon[ch] * length), 1.0, 1e-3) << "channel " << ch;
}

// A fire written as Blender writes one: a flame grid f = 1 in a ball of
// radius 0.1 m, imported with flame_temperature 1706.85 K (T = 2000 K in the
// ball) and flame_absorption 5 /m. The centre pixel's radiance is
// B_rgb(2000 K)·(1 − e^{−5·chord}) plus the background through the soot,
// within 0.5%, with the chord of the voxelized ball (0.208 m for 0.2 m);
// pixels whose rays pass two voxels clear of the ball are bit-identical to
// the same scene with emission "none" (the soot still absorbs there, the
// glow adds nothing), and the glowing image is brighter where the flame is.
TEST(VolumeEmission, ABlackbodyFlameGlowsWhereTheFlameIs) {
    const fs::path folder = fs::path(::testing::TempDir()) / "eikon_volume_emission";
    fs::create_directories(folder);
    const double radius = 0.1, h = 0.5 / 48;
    // Voxel (i,j,k) at (i,j,k)·h, shifted half a voxel by volume.offset onto the render cells' centres.
    writeVdbFile(folder / "fire.vdb",
                 {{"flame", 1, [&](double x, double y, double z, int) {
                       const glm::dvec3 p = glm::dvec3(x, y, z) + 0.5 * h;
                       return glm::length(p) < radius ? 1.0f : 0.0f;
                   }}},
                 h, -0.3, 0.3);
    const std::string json = R"({
      "grid": {"bounds": {"min": [-0.25, -0.25, -0.25], "max": [0.25, 0.25, 0.25]}, "resolution": [48, 48, 48]},
      "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1]}],
      "camera": {"position": [0, 0, 1.5], "target": [0, 0, 0], "fov_deg": 24},
      "render": {"width": 33, "height": 33, "photons": 64, "background": [0.5, 0.5, 0.5]},
      "volume": {"path": "fire.vdb", "grids": {"density": "", "temperature": "", "flame": "flame"},
                 "offset": [)" + std::to_string(0.5 * h) + ", " + std::to_string(0.5 * h) + ", " +
                             std::to_string(0.5 * h) + R"(],
                 "flame_temperature": 1706.85, "flame_absorption": 5, "emission": "blackbody"}
    })";
    std::ofstream(folder / "fire.json") << json;
    const Scene glowing = loadSceneFile((folder / "fire.json").string(), {});
    const Scene dark = loadSceneFile((folder / "fire.json").string(), {"volume.emission=\"none\""});
    const sim::SceneFields glowingFields(glowing), darkFields(dark);
    ASSERT_TRUE(glowingFields.fields().hasEmission());
    ASSERT_FALSE(darkFields.fields().hasEmission());
    const std::vector<float> lit = renderHdr(glowing, glowingFields.fields());
    const std::vector<float> unlit = renderHdr(dark, darkFields.fields());

    // The centre pixel's ray runs along z between four columns of cells; each
    // holds the same count of cells whose centres lie in the ball, and the
    // trilinear κ integrates to 5 /m times that count times h.
    int inBall = 0;
    for (int k = 0; k < 48; ++k) inBall += std::hypot(0.5 * h, 0.5 * h, -0.25 + (k + 0.5) * h) < radius;
    const int centre = 16 * 33 + 16;
    const glm::dvec3 planck = sim::blackbodyRgb(2000.0);
    const double transmittance = std::exp(-5.0 * inBall * h);
    for (int ch = 0; ch < 3; ++ch) {
        const double expected = planck[ch] * (1.0 - transmittance) + 0.5 * transmittance;  // glow + background
        reportFigure(("flame_centre_measured_over_closed_form_channel_" + std::to_string(ch)).c_str(),
                     lit[4 * centre + ch] / expected);
        EXPECT_NEAR(lit[4 * centre + ch] / expected, 1.0, 0.005) << "channel " << ch;
    }
    // Pixel (i, j) looks along a ray whose closest approach to the centre is
    // about 1.5 m · tan of its angle off the axis.
    const double pixelAngle = std::tan(12.0 * 3.14159265358979 / 180.0) / 16.5;
    int clear = 0, differing = 0;
    for (int j = 0; j < 33; ++j)
        for (int i = 0; i < 33; ++i) {
            const double offAxis = 1.5 * pixelAngle * std::hypot(i - 16.0, j - 16.0);
            if (offAxis < radius + 2.0 * 0.5 / 48 + 0.02) continue;
            ++clear;
            for (int ch = 0; ch < 3; ++ch) differing += lit[4 * (j * 33 + i) + ch] != unlit[4 * (j * 33 + i) + ch];
        }
    EXPECT_GT(clear, 400);
    EXPECT_EQ(differing, 0);
    EXPECT_GT(lit[4 * centre], 100.0 * unlit[4 * centre]) << "the flame glows red-hot over the soot's shadow";
    fs::remove_all(folder);
}

// Solid angle of the rectangle [0, a] × [0, b] seen from height h above its
// corner (a, b ≥ 0).
double cornerRectangleSolidAngle(double a, double b, double h) {
    return std::atan(a * b / (h * std::sqrt(a * a + b * b + h * h)));
}

// Gauss–Legendre nodes and weights on [0, 1], 8 points.
struct Quadrature {
    double x[8], w[8];
};
Quadrature gaussLegendre8() {
    const double nodes[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
    const double weights[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
    Quadrature q{};
    for (int i = 0; i < 4; ++i) {
        q.x[i] = 0.5 * (1.0 - nodes[i]);
        q.x[7 - i] = 0.5 * (1.0 + nodes[i]);
        q.w[i] = q.w[7 - i] = 0.5 * weights[i];
    }
    return q;
}

// A cube of side 0.1 m centred 0.3 m up glows with ε = (1, 2, 3)
// W/(m³·sr) in clear air, the scene's only light (volume.emission_lights);
// a floor receiver 2 m wide lies 0.05 m below the grid. Against quadratures
// of the cube (8³ Gauss points, independent of the renderer):
//   emitted   = 4π·V·ε, to float rounding (1e-5);
//   received  = ε·∫ Ω(p) dV, Ω the floor's solid angle from p, within 0.5%
//               (2^20 photons: 0.1% noise);
//   E centre  = ε·∫ h/r³ dV averaged over the central 4×4 texels, within 3%
//               (15 000 photons there: 0.8% noise).
TEST(VolumeEmission, AGlowingVolumeLightsTheFloorAsItsRadiometrySays) {
    Scene scene = emptyScene(glm::dvec3(-0.25, 0.0, -0.25), glm::dvec3(0.25, 0.5, 0.25), 20);
    scene.render.photons = 1 << 20;
    const double floorY = -0.05, size = 2.0;
    scene.receivers.push_back(floorReceiver(floorY, size, 32));
    scene.receivers.back().filter = ReceiverDesc::Filter::None;
    VolumeDesc volume;
    volume.emissionLights = true;
    scene.volume = volume;
    FieldSet fields;
    fields.grid = scene.grid.spec();
    fields.deltaIndex.assign(fields.grid.cellCount(), 0.0f);
    fields.emission.assign(3 * fields.grid.cellCount(), 0.0f);
    const glm::dvec3 epsilon(1.0, 2.0, 3.0);
    for (int k = 8; k < 12; ++k)  // x, z in [−0.05, 0.05], y in [0.25, 0.35]: 4³ cells of 0.025 m
        for (int j = 10; j < 14; ++j)
            for (int i = 8; i < 12; ++i)
                for (int ch = 0; ch < 3; ++ch)
                    fields.emission[3 * fields.grid.linearIndex(i, j, k) + ch] = static_cast<float>(epsilon[ch]);
    fields.indexVersion = fields.extinctionVersion = 1;
    const TraceResult result = traceFields(scene, fields);

    const Quadrature q = gaussLegendre8();
    const double side = 0.1, volumeOfCube = side * side * side, half = 0.5 * size;
    const double texel = size / 32.0, block = 4.0 * texel;
    double solidAngleIntegral = 0.0, centreIrradiance = 0.0;  // per unit ε
    for (int a = 0; a < 8; ++a)
        for (int b = 0; b < 8; ++b)
            for (int c = 0; c < 8; ++c) {
                const glm::dvec3 p(-0.05 + side * q.x[a], 0.25 + side * q.x[b], -0.05 + side * q.x[c]);
                const double weight = q.w[a] * q.w[b] * q.w[c] * volumeOfCube;
                const double h = p.y - floorY;
                double omega = 0.0;
                for (double sx : {-1.0, 1.0})
                    for (double sz : {-1.0, 1.0}) omega += cornerRectangleSolidAngle(half - sx * p.x, half - sz * p.z, h);
                solidAngleIntegral += weight * omega;
                for (int u = 0; u < 8; ++u)
                    for (int v = 0; v < 8; ++v) {
                        const glm::dvec3 point(-0.5 * block + block * q.x[u], floorY, -0.5 * block + block * q.x[v]);
                        const double r = glm::length(p - point);
                        centreIrradiance += weight * q.w[u] * q.w[v] * h / (r * r * r);
                    }
            }
    double received[3] = {0, 0, 0}, centre[3] = {0, 0, 0};
    for (int j = 0; j < 32; ++j)
        for (int i = 0; i < 32; ++i)
            for (int ch = 0; ch < 3; ++ch) {
                const double value = result.map[3 * (j * 32 + i) + ch];
                received[ch] += value * texel * texel;
                if (i >= 14 && i < 18 && j >= 14 && j < 18) centre[ch] += value / 16.0;
            }
    for (int ch = 0; ch < 3; ++ch) {
        EXPECT_NEAR(result.stats.emitted[ch] / (4.0 * std::numbers::pi * volumeOfCube * epsilon[ch]), 1.0, 1e-5);
        const double receivedRatio = received[ch] / (epsilon[ch] * solidAngleIntegral);
        const double centreRatio = centre[ch] / (epsilon[ch] * centreIrradiance);
        reportFigure(("glow_received_over_quadrature_channel_" + std::to_string(ch)).c_str(), receivedRatio);
        reportFigure(("glow_centre_irradiance_over_quadrature_channel_" + std::to_string(ch)).c_str(), centreRatio);
        EXPECT_NEAR(receivedRatio, 1.0, 0.005) << "channel " << ch;
        EXPECT_NEAR(centreRatio, 1.0, 0.03) << "channel " << ch;
    }
}

}  // namespace
}  // namespace eikon
