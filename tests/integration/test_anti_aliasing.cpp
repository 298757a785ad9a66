// Anti-aliasing (render.samples_per_pixel, render/stages/PixelSamples.h): a
// checkerboard ground seen at grazing incidence, 5° to 35° below the horizon
// from 1 m up, where the squares shrink from many pixels to far below one.
// The box filter's exact pixel is the checkerboard's mean over the pixel's
// footprint; the 256-sample image of the renderer is checked against that
// integral computed here independently (4096 pinhole rays per pixel, one
// at a random point of each cell of a 64 × 64 grid, in double precision,
// intersected with the plane), and each sample count against the 256-sample
// image: relative L1 = Σ|I − I_ref| / Σ I_ref over every pixel and channel.
// One ray a pixel through its centre, the checkerboard point-sampled (the
// renderer before samples_per_pixel), was 35% from the reference.
#include "render/graph/FrameRenderer.h"
#include "render/stages/PixelSamples.h"
#include "sim/voxelize/AnalyticVoxelizer.h"
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace eikon {
namespace {

using namespace test;

constexpr int kWidth = 160, kHeight = 120;
constexpr double kFovDeg = 30.0, kDownDeg = 20.0, kHeightM = 1.0, kChecker = 0.1;
constexpr double kLight = 0.8, kDark = 0.05;

Scene grazingCheckerboard() {
    // The grid, which the rays never meet, sits behind the camera.
    Scene scene = emptyScene(glm::dvec3(-0.1, 2.0, 2.0), glm::dvec3(0.1, 2.2, 2.2), 8);
    scene.lights.push_back(directionalLight({0.0, -1.0, 0.0}, 1.0));
    scene.render.width = kWidth;
    scene.render.height = kHeight;
    scene.render.errorEstimate = false;
    EnvironmentDesc& ground = scene.render.environment;
    ground.kind = EnvironmentDesc::Kind::Sky;
    ground.groundHeight = 0.0;
    ground.checkerSize = kChecker;
    ground.groundA = Rgb(kLight);
    ground.groundB = Rgb(kDark);
    scene.camera.position = glm::dvec3(0.0, kHeightM, 0.0);
    scene.camera.target = scene.camera.position + glm::dvec3(0.0, -std::tan(glm::radians(kDownDeg)), -1.0);
    scene.camera.up = glm::dvec3(0.0, 1.0, 0.0);
    scene.camera.fovDeg = kFovDeg;
    return scene;
}

std::vector<float> render(Scene scene, int samples) {
    scene.render.samplesPerPixel = samples;
    const FieldSet fields = sim::voxelizeScene(scene);
    render::FrameRenderer renderer(scene, fields, {.photons = {}});
    renderer.render(fields);
    return renderer.viewStage().downloadHdr();
}

// The pixel's mean radiance under a box filter, by 4096 stratified random
// rays through it: the camera model of docs/scene-format.md, written afresh.
std::vector<float> boxFilteredByGrid() {
    const int n = 64;
    std::mt19937 random(54);
    std::uniform_real_distribution<double> jitter(0.0, 1.0);
    const glm::dvec3 position(0.0, kHeightM, 0.0);
    const glm::dvec3 forward = glm::normalize(glm::dvec3(0.0, -std::tan(glm::radians(kDownDeg)), -1.0));
    const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0)));
    const glm::dvec3 up = glm::cross(right, forward);
    const double half = std::tan(glm::radians(kFovDeg) / 2), aspect = double(kWidth) / kHeight;
    std::vector<float> image(4u * kWidth * kHeight);
    for (int py = 0; py < kHeight; ++py)
        for (int px = 0; px < kWidth; ++px) {
            double sum = 0.0;
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    const double u = ((px + (i + jitter(random)) / n) / kWidth) * 2.0 - 1.0;
                    const double v = ((py + (j + jitter(random)) / n) / kHeight) * 2.0 - 1.0;
                    const glm::dvec3 d = glm::normalize(forward + u * half * aspect * right - v * half * up);
                    const glm::dvec3 hit = position + (kHeightM / -d.y) * d;  // every ray looks down
                    const long long parity = static_cast<long long>(std::floor(hit.x / kChecker)) +
                                             static_cast<long long>(std::floor(hit.z / kChecker));
                    sum += (parity & 1) == 0 ? kLight : kDark;
                }
            for (int c = 0; c < 3; ++c) image[4u * (py * kWidth + px) + c] = static_cast<float>(sum / (n * n));
        }
    return image;
}

double relativeL1(const std::vector<float>& image, const std::vector<float>& reference) {
    double difference = 0.0, total = 0.0;
    for (std::size_t i = 0; i < reference.size(); ++i) {
        if (i % 4 == 3) continue;  // alpha
        difference += std::abs(double(image[i]) - reference[i]);
        total += reference[i];
    }
    return difference / total;
}

TEST(PixelSamples, TheGridsCellCentresTileThePixel) {
    EXPECT_EQ(render::sampleGridSide(1), 1);
    EXPECT_EQ(render::sampleGridSide(16), 4);
    EXPECT_EQ(render::sampleGridSide(8), 0);
    const glm::vec2 centre = render::gridSampleOffset(0, 1);
    EXPECT_EQ(centre.x, 0.5f);
    EXPECT_EQ(centre.y, 0.5f);
    for (int k : {2, 3, 5}) {
        std::vector<int> hits(k * k, 0);
        for (int cell = 0; cell < k * k; ++cell) {
            const glm::vec2 offset = render::gridSampleOffset(cell, k);
            const glm::vec2 scaled = offset * static_cast<float>(k);
            EXPECT_NEAR(scaled.x - std::floor(scaled.x), 0.5f, 1e-5f) << "a cell's centre";
            EXPECT_NEAR(scaled.y - std::floor(scaled.y), 0.5f, 1e-5f) << "a cell's centre";
            ++hits[static_cast<int>(scaled.y) * k + static_cast<int>(scaled.x)];
        }
        for (int hit : hits) EXPECT_EQ(hit, 1) << "each cell of the " << k << " × " << k << " grid once";
    }
}

TEST(AntiAliasing, GrazingCheckerboardConvergesToTheBoxFilteredImage) {
    glContext();
    const Scene scene = grazingCheckerboard();
    const std::vector<float> reference = render(scene, 256);

    // The picture is not trivial: the near rows resolve the squares (dark and
    // light pixels), the far ones average them to grey.
    const auto pixel = [&](int x, int y) { return reference[4u * (y * kWidth + x)]; };
    float nearDarkest = 1.0f, nearLightest = 0.0f, farDarkest = 1.0f, farLightest = 0.0f;
    for (int x = 0; x < kWidth; ++x) {
        nearDarkest = std::min(nearDarkest, pixel(x, kHeight - 2));
        nearLightest = std::max(nearLightest, pixel(x, kHeight - 2));
        farDarkest = std::min(farDarkest, pixel(x, 1));
        farLightest = std::max(farLightest, pixel(x, 1));
    }
    EXPECT_LT(nearDarkest, 0.1f);
    EXPECT_GT(nearLightest, 0.75f);
    EXPECT_GT(farDarkest, 0.3f) << "far squares average out";
    EXPECT_LT(farLightest, 0.55f) << "far squares average out";

    const double referenceError = relativeL1(reference, boxFilteredByGrid());
    reportFigure("anti_aliasing_256_spp_l1_vs_box_integral", referenceError);
    EXPECT_LT(referenceError, 0.002) << "256 samples are the box filter's image";

    for (int samples : {1, 4, 9, 16, 64}) {
        const double error = relativeL1(render(scene, samples), reference);
        reportFigure(("anti_aliasing_l1_" + std::to_string(samples) + "_spp").c_str(), error);
        if (samples == 1) {
            EXPECT_GT(error, 0.01) << "one ray a pixel aliases";
        }
    }
    const double atDefault = relativeL1(render(scene, RenderDesc{}.samplesPerPixel), reference);
    reportFigure("anti_aliasing_l1_default_spp", atDefault);
    EXPECT_LE(atDefault, 0.01) << "at the default render.samples_per_pixel = " << RenderDesc{}.samplesPerPixel;
}

// The viewer's progressive view: a changed frame is the image of
// render.samples_per_pixel (4: the 2×2 grid), as `eikon run` draws it; each
// frame in which nothing changes adds a pass of the next finer grid to the
// mean, which after the 3×3 grid is (4·I₄ + 9·I₉)/13, and it stops once the
// 5×5 grid is whole (4 + 9 + 16 + 25 passes); a moved camera starts again.
TEST(AntiAliasing, TheProgressiveViewAddsFinerGridsWhileNothingChanges) {
    glContext();
    Scene scene = grazingCheckerboard();
    const std::vector<float> four = render(scene, 4), nine = render(scene, 9);
    const FieldSet fields = sim::voxelizeScene(scene);
    render::FrameRenderer renderer(scene, fields, {.photons = {}, .progressiveView = true});
    const auto ran = [](const render::FrameResult& frame, const char* name) {
        for (const render::StageReport& stage : frame.stages)
            if (stage.name == name) return stage.ran;
        return false;
    };
    render::FrameResult frame = renderer.render(fields);
    EXPECT_EQ(frame.viewSamples, 4);
    EXPECT_EQ(renderer.viewStage().downloadHdr(), four) << "the frame eikon run draws";
    for (int pass = 5; pass <= 13; ++pass) {
        frame = renderer.render(fields);
        EXPECT_TRUE(ran(frame, "view_refine"));
        EXPECT_FALSE(ran(frame, "view"));
        EXPECT_EQ(frame.viewSamples, pass);
    }
    const std::vector<float> mean = renderer.viewStage().downloadHdr();
    double worst = 0.0;
    for (std::size_t i = 0; i < mean.size(); ++i)
        worst = std::max(worst, std::abs(mean[i] - (4.0 * four[i] + 9.0 * nine[i]) / 13.0));
    EXPECT_LT(worst, 1e-5) << "the mean of the 2×2 and 3×3 grids";
    for (int pass = 14; pass <= 54; ++pass) frame = renderer.render(fields);
    EXPECT_EQ(frame.viewSamples, 54);
    frame = renderer.render(fields);
    EXPECT_FALSE(ran(frame, "view_refine")) << "it stops once the 5×5 grid is whole";
    EXPECT_EQ(frame.viewSamples, 54);
    CameraDesc moved = scene.camera;
    moved.position.x += 0.01;
    renderer.setCamera(moved);
    frame = renderer.render(fields);
    EXPECT_TRUE(ran(frame, "view"));
    EXPECT_EQ(frame.viewSamples, 4);
}

}  // namespace
}  // namespace eikon
