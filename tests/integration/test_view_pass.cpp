// The viewing pass against closed forms: heat-shimmer deflection through a
// Gaussian hot-air bump, single scattering in a homogeneous slab, total
// internal reflection in glass, a ground just below the grid's floor; and the
// default picture against a reference.
#include "bridge/core/Error.h"
#include "io/image/ImageIo.h"
#include "io/scene/SceneParser.h"
#include "render/graph/FrameRenderer.h"
#include "sim/voxelize/AnalyticVoxelizer.h"
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"
#include "verify/reference/PinholeCamera.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace eikon {
namespace {

using namespace test;

struct ViewResult {
    std::vector<float> hdr;
    std::vector<glm::vec4> exits;
    render::Image8 image;
};

ViewResult view(const Scene& scene, const FieldSet& fields) {
    glContext();
    render::FrameRenderer renderer(scene, fields, {.photons = {}, .recordViewExits = true});
    ViewResult result;
    result.image = renderer.render(fields).image;
    result.hdr = renderer.viewStage().downloadHdr();
    result.exits = renderer.viewStage().downloadExits();
    return result;
}

// Heat shimmer: hot air lowers the index, δn = A·exp(−r²/2s²) with A < 0. A
// ray passing at impact parameter b is deflected (thin-lens approximation,
// n ≈ 1) by α = ∫ ∂n/∂x dz = −A·b·√(2π)/s · exp(−b²/2s²), away from the bump.
// Each pixel's exit direction must match within 5% wherever α exceeds a
// fifth of its peak — which is how far a background checkerboard is shifted.
TEST(ViewPass, HeatShimmerDeflectsByTheAnalyticAngle) {
    const double amplitude = -1e-3, width = 0.04;
    Scene scene = emptyScene(glm::dvec3(-0.25), glm::dvec3(0.25), 80);
    scene.grid.smoothingSigmaVoxels = 0.0;
    scene.lights.push_back(directionalLight({0.0, -1.0, 0.0}, 1.0));
    scene.render.photons = 64;
    scene.render.width = 161;
    scene.render.height = 3;
    scene.camera.position = glm::dvec3(0.0, 0.0, 4.0);
    scene.camera.target = glm::dvec3(0.0);
    scene.camera.fovDeg = 0.08;  // × aspect 161/3: the row spans ±0.15 m at the bump, nearly parallel rays
    FieldSet fields;
    fields.grid = scene.grid.spec();
    fields.deltaIndex.resize(fields.grid.cellCount());
    for (int k = 0; k < 80; ++k)
        for (int j = 0; j < 80; ++j)
            for (int i = 0; i < 80; ++i) {
                const glm::dvec3 x = fields.grid.cellCentre(i, j, k);
                fields.deltaIndex[fields.grid.linearIndex(i, j, k)] =
                    static_cast<float>(amplitude * std::exp(-glm::dot(x, x) / (2 * width * width)));
            }
    fields.indexVersion = 1;
    const ViewResult result = view(scene, fields);

    const double peak = -amplitude * std::sqrt(2 * std::numbers::pi) * std::exp(-0.5);  // at b = s
    double worst = 0.0;
    int checked = 0;
    for (int i = 0; i < scene.render.width; ++i) {
        const glm::dvec3 initial = reference::pixelDirection(scene.camera, scene.render.width, scene.render.height, i, 1);
        const glm::dvec3 exit(result.exits[static_cast<std::size_t>(scene.render.width + i)]);
        // Impact parameter: closest approach of the undeflected ray to the bump's centre.
        const glm::dvec3 toCentre = -scene.camera.position;
        const double b = (scene.camera.position + glm::dot(toCentre, initial) * initial).x;
        const double expected = -amplitude * b * std::sqrt(2 * std::numbers::pi) / width * std::exp(-b * b / (2 * width * width));
        if (std::abs(expected) < 0.2 * peak) continue;
        const double measured = exit.x - initial.x;  // small angles
        worst = std::max(worst, std::abs(measured / expected - 1.0));
        ++checked;
    }
    reportFigure("heat_shimmer_deflection_worst_relative_error", worst);
    EXPECT_GT(checked, 40);
    EXPECT_LT(worst, 0.05);
}

// Single scattering: a homogeneous slab (σs = κ = 2 /m, g = 0) fills the grid
// under a vertical beam E0; a horizontal camera ray at depth d crosses
// L = 0.5 m of it and sees
//   L = σs · φ(d) · p · (1 − e^{−κL}) / κ,   φ(d) = E0·e^{−κd},  p = 1/4π
// (no background). The centre pixel must match within 3%.
TEST(ViewPass, SingleScatteringMatchesTheSlabClosedForm) {
    Scene scene = emptyScene(glm::dvec3(-0.25, 0.0, -0.25), glm::dvec3(0.25, 0.5, 0.25), 32);
    scene.medium.extinction = Rgb(2.0);
    scene.medium.scattering = Rgb(2.0);
    scene.lights.push_back(directionalLight({0.0, -1.0, 0.0}, 3.0));
    scene.render.photons = 1 << 19;
    scene.render.width = 9;
    scene.render.height = 9;
    scene.render.environment.radiance = Rgb(0.0);
    scene.camera.position = glm::dvec3(-1.0, 0.3, 0.0);
    scene.camera.target = glm::dvec3(0.0, 0.3, 0.0);
    scene.camera.fovDeg = 1.0;
    const ViewResult result = view(scene, sim::voxelizeScene(scene));

    const double kappa = 2.0, sigma = 2.0, depth = 0.2, length = 0.5;
    const double expected = sigma * 3.0 * std::exp(-kappa * depth) / (4 * std::numbers::pi) *
                            (1 - std::exp(-kappa * length)) / kappa;
    const double measured = result.hdr[4 * (4 * 9 + 4) + 1];
    reportFigure("single_scattering_measured_over_closed_form", measured / expected);
    EXPECT_NEAR(measured / expected, 1.0, 0.03);
}

// Total internal reflection: inside glass (n = 1.5) a camera ray meets the
// flat top surface at 60° from its normal, beyond the critical angle 41.8°,
// and the ray equation alone must turn it back down; at 30° it leaves
// upward, bent away from the normal by Snell's law.
TEST(ViewPass, TotalInternalReflectionComesFromTheRayEquation) {
    for (double angle : {30.0, 60.0}) {
        Scene scene = emptyScene(glm::dvec3(-0.5), glm::dvec3(0.5), 64);
        ObjectDesc glass;
        glass.kind = ObjectDesc::Kind::Box;
        glass.box = {glm::dvec3(-2.0), glm::dvec3(2.0, 0.0, 2.0)};
        glass.material.index = 1.5;
        scene.objects.push_back(glass);
        scene.lights.push_back(directionalLight({0.0, -1.0, 0.0}, 1.0));
        scene.render.photons = 64;
        scene.render.width = 3;
        scene.render.height = 3;
        const double radians = angle * std::numbers::pi / 180.0;
        scene.camera.position = glm::dvec3(-0.2, -0.2, 0.0);
        scene.camera.target = scene.camera.position + glm::dvec3(std::sin(radians), std::cos(radians), 0.0);
        scene.camera.up = glm::dvec3(0.0, 0.0, 1.0);
        scene.camera.fovDeg = 1.0;
        const ViewResult result = view(scene, sim::voxelizeScene(scene));
        const glm::vec4 exit = result.exits[4];
        reportFigure(angle > 41.8 ? "tir_reflected_exit_x_minus_sin60" : "refraction_exit_angle_error_rad",
                     angle > 41.8 ? exit.x - std::sin(radians) : std::asin(exit.x) - std::asin(1.5 * std::sin(radians)));
        if (angle > 41.8) {
            EXPECT_LT(exit.y, 0.0f) << "at " << angle << "°, the ray must be reflected back into the glass";
            EXPECT_NEAR(exit.x, std::sin(radians), 0.02) << "mirror reflection keeps the tangential component";
        } else {
            const double refracted = std::asin(1.5 * std::sin(radians));  // Snell, into air
            EXPECT_GT(exit.y, 0.0f) << "at " << angle << "°, the ray must leave the glass";
            EXPECT_NEAR(std::asin(exit.x), refracted, 0.01) << "Snell's law";
        }
    }
}

// A ground plane 1 mm below the grid's floor, seen through a graded field
// (camera steps of a 10 cm voxel): a ray that steps out through the floor
// overshoots it by up to a step, below the ground, and must still meet the
// ground where its straight line does (the field bends it by ~1e-7 rad).
// Every pixel whose ray meets the ground at least 2 cm inside a 10 cm
// checker square must show that square's colour.
TEST(ViewPass, AGroundJustBelowTheGridFloorIsSeenWhereTheRayMeetsIt) {
    const double ground = -0.001, square = 0.1;
    Scene scene = emptyScene(glm::dvec3(-0.5, 0.0, -0.5), glm::dvec3(0.5), 10);
    scene.grid.smoothingSigmaVoxels = 0.0;
    scene.lights.push_back(directionalLight({0.0, -1.0, 0.0}, 1.0));
    scene.render.photons = 64;
    scene.render.width = 160;
    scene.render.height = 120;
    scene.render.samplesPerPixel = 1;
    EnvironmentDesc& sky = scene.render.environment;
    sky.kind = EnvironmentDesc::Kind::Sky;
    sky.groundHeight = ground;
    sky.checkerSize = square;
    sky.groundA = Rgb(0.8);
    sky.groundB = Rgb(0.05);
    scene.camera.position = glm::dvec3(0.05, 1.2, 1.7);
    scene.camera.target = glm::dvec3(0.0, 0.0, 0.0);
    scene.camera.fovDeg = 30.0;
    FieldSet fields;
    fields.grid = scene.grid.spec();
    fields.deltaIndex.resize(fields.grid.cellCount());
    for (int k = 0; k < 10; ++k)
        for (int j = 0; j < 10; ++j)
            for (int i = 0; i < 10; ++i) {  // no two cells alike: no step spans more than the step length
                const glm::dvec3 x = fields.grid.cellCentre(i, j, k);
                fields.deltaIndex[fields.grid.linearIndex(i, j, k)] = static_cast<float>(1e-7 * (x.x + 2.0 * x.y + 3.0 * x.z));
            }
    fields.indexVersion = 1;
    const ViewResult result = view(scene, fields);

    int checked = 0, wrong = 0;
    for (int j = 0; j < scene.render.height; ++j)
        for (int i = 0; i < scene.render.width; ++i) {
            const glm::dvec3 d = reference::pixelDirection(scene.camera, scene.render.width, scene.render.height, i, j);
            if (d.y >= 0.0) continue;
            const glm::dvec3 hit = scene.camera.position + (ground - scene.camera.position.y) / d.y * d;
            if (std::abs(hit.x) > 0.5 || std::abs(hit.z) > 0.5) continue;  // only rays that leave through the floor
            const double u = hit.x / square, w = hit.z / square;
            const double fu = u - std::floor(u), fw = w - std::floor(w);
            if (std::min(fu, 1.0 - fu) < 0.2 || std::min(fw, 1.0 - fw) < 0.2) continue;  // near a line: filtered
            const bool first = ((static_cast<long>(std::floor(u)) + static_cast<long>(std::floor(w))) & 1) == 0;
            const double expected = first ? 0.8 : 0.05;
            const double seen = result.hdr[4 * static_cast<std::size_t>(j * scene.render.width + i) + 1];
            ++checked;
            if (std::abs(seen - expected) > 0.01) ++wrong;
        }
    reportFigure("ground_below_floor_wrong_square_pixels", wrong);
    EXPECT_GT(checked, 2000);
    EXPECT_EQ(wrong, 0) << "of " << checked << " pixels";
}

// The default scene (reduced) against a reference picture made by this
// code: per-pixel absolute difference in 8-bit sRGB, 99th percentile ≤ 6
// levels and mean ≤ 1 level (room for other GPUs' arithmetic, not for a
// changed picture), and the picture must not be blank.
TEST(ViewPass, DefaultPictureMatchesReference) {
    glContext();
    const Scene scene = loadSceneFile(std::string(EIKON_SOURCE_DIR) + "/scenes/default.json",
                                      {"grid.resolution=[48,40,48]", "render.photons=262144", "render.width=160",
                                       "render.height=120", "receivers.0.resolution=96"});
    const FieldSet fields = sim::voxelizeScene(scene);
    render::FrameRenderer renderer(scene, fields);
    const render::Image8 image = renderer.render(fields).image;
    const io::Rgba8Image reference = io::readImage(std::string(EIKON_SOURCE_DIR) + "/tests/data/default_reference.png");
    ASSERT_EQ(reference.width, image.width);
    ASSERT_EQ(reference.height, image.height);
    std::vector<int> differences;
    double sum = 0.0;
    int distinct = 0;
    for (std::size_t p = 0; p < image.rgba.size(); ++p) {
        if (p % 4 == 3) continue;
        const int difference = std::abs(int{image.rgba[p]} - int{reference.rgba[p]});
        differences.push_back(difference);
        sum += difference;
        distinct += image.rgba[p] != image.rgba[p % 4];
    }
    std::sort(differences.begin(), differences.end());
    const int percentile99 = differences[differences.size() * 99 / 100];
    reportFigure("reference_picture_p99_difference_levels", percentile99);
    reportFigure("reference_picture_mean_difference_levels", sum / static_cast<double>(differences.size()));
    EXPECT_LE(percentile99, 6);
    EXPECT_LE(sum / static_cast<double>(differences.size()), 1.0);
    EXPECT_GT(distinct, static_cast<int>(differences.size() / 4)) << "a picture of one colour is blank";
}

// The viewer's preview (a pixel stride k): each k×k block of the image is
// the pixel at the block's centre of the full image of one ray a pixel
// (through each pixel's centre), the blocks at the right and
// bottom edges cut short; back at stride 1 the image is the full one again,
// bit for bit, and only the view and post stages ran for either change.
TEST(ViewPass, APreviewFillsBlocksWithTheFullImagesCentrePixel) {
    glContext();
    const Scene scene = loadSceneFile(std::string(EIKON_SOURCE_DIR) + "/scenes/default.json",
                                      {"grid.resolution=[48,40,48]", "render.photons=65536", "render.width=160",
                                       "render.height=121", "receivers.0.resolution=96",
                                       "render.samples_per_pixel=1"});
    const FieldSet fields = sim::voxelizeScene(scene);
    render::FrameRenderer renderer(scene, fields);
    const render::Image8 full = renderer.render(fields).image;
    const std::vector<float> fullHdr = renderer.viewStage().downloadHdr();
    const int width = scene.render.width, height = scene.render.height;
    for (int stride : {3, 8}) {
        renderer.setPixelStride(stride);
        const render::FrameResult preview = renderer.render(fields);
        EXPECT_EQ(preview.pixelStride, stride);
        for (const render::StageReport& stage : preview.stages)
            EXPECT_EQ(stage.ran, stage.name == "view" || stage.name == "post") << stage.name << ", stride " << stride;
        const std::vector<float> hdr = renderer.viewStage().downloadHdr();
        int mismatched = 0;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const int cx = std::min(x / stride * stride + stride / 2, width - 1);
                const int cy = std::min(y / stride * stride + stride / 2, height - 1);
                for (int c = 0; c < 4; ++c)
                    mismatched += hdr[4 * (y * width + x) + c] != fullHdr[4 * (cy * width + cx) + c];
            }
        EXPECT_EQ(mismatched, 0) << "stride " << stride;
    }
    renderer.setPixelStride(1);
    const render::FrameResult again = renderer.render(fields);
    EXPECT_EQ(again.pixelStride, 1);
    EXPECT_EQ(again.image.rgba, full.rgba);
    EXPECT_EQ(renderer.viewStage().downloadHdr(), fullHdr);
}

// Wider than a 1D dispatch can cover (16 384 × 480 pixels: 122 880 groups of
// 64, past the 65 535 OpenGL guarantees) the image still renders; larger
// than the biggest storage buffer the context has, it is refused at its key
// path with the size and the limit, before anything is traced.
TEST(ViewPass, ImageSizesAreCheckedAgainstTheContextsLimits) {
    glContext();
    const std::string path = std::string(EIKON_SOURCE_DIR) + "/scenes/default.json";
    const Scene wide = loadSceneFile(path, {"grid.resolution=[24,20,24]", "render.photons=4096", "render.width=16384",
                                            "render.height=480", "receivers.0.resolution=32"});
    const FieldSet fields = sim::voxelizeScene(wide);
    render::FrameRenderer renderer(wide, fields);
    const render::Image8 image = renderer.render(fields).image;
    ASSERT_EQ(image.width, 16384);
    const std::size_t middle = (static_cast<std::size_t>(image.height / 2) * image.width + image.width / 2) * 4;
    EXPECT_GT(image.rgba[middle] + image.rgba[middle + 1] + image.rgba[middle + 2], 0) << "the sphere is not black";

    GLint64 largest = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &largest);
    const long long height = largest / (16LL * 16384) + 1;  // one row more than fits
    if (height > 16384) GTEST_SKIP() << "this context's storage buffers hold any image the scene format allows";
    const Scene tall = loadSceneFile(path, {"grid.resolution=[24,20,24]", "render.width=16384",
                                            "render.height=" + std::to_string(height)});
    try {
        render::FrameRenderer refused(tall, fields);
        FAIL() << "an image larger than the context's storage buffers was accepted";
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_EQ(message.rfind(tall.sourcePath + ": render.width × render.height: expected", 0), 0u)
            << "the scene file and the keys, once: " << message;
        EXPECT_NE(message.find(std::to_string(largest)), std::string::npos) << message;
    }
}

}  // namespace
}  // namespace eikon
