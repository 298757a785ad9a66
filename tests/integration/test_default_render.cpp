// The default scene end to end, at a reduced size: a glass sphere above a
// diffuse floor lit by a point light must focus a caustic onto the floor.
#include "io/scene/SceneParser.h"
#include "render/graph/FrameRenderer.h"
#include "sim/voxelize/AnalyticVoxelizer.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <cmath>

namespace eikon {
namespace {

Scene reducedDefaultScene() {
    return loadSceneFile(std::string(EIKON_SOURCE_DIR) + "/scenes/default.json",
                         {"grid.resolution=[48,40,48]", "render.photons=262144", "render.width=200",
                          "render.height=150", "receivers.0.resolution=96"});
}

// Pixel (x, y) where a world point appears, by the view shader's camera model.
glm::dvec2 projectToPixel(const Scene& scene, const glm::dvec3& point) {
    const glm::dvec3 forward = glm::normalize(scene.camera.target - scene.camera.position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, scene.camera.up));
    const glm::dvec3 up = glm::cross(right, forward);
    const glm::dvec3 d = point - scene.camera.position;
    const double depth = glm::dot(d, forward);
    const double tanHalf = std::tan(scene.camera.fovDeg * M_PI / 360.0);
    const double aspect = static_cast<double>(scene.render.width) / scene.render.height;
    const double ndcX = glm::dot(d, right) / (depth * tanHalf * aspect);
    const double ndcY = -glm::dot(d, up) / (depth * tanHalf);
    return {(ndcX + 1.0) / 2.0 * scene.render.width - 0.5, (ndcY + 1.0) / 2.0 * scene.render.height - 0.5};
}

double meanLuminance(const render::Image8& image, glm::dvec2 centre, int radius) {
    double sum = 0.0;
    int count = 0;
    for (int y = static_cast<int>(centre.y) - radius; y <= static_cast<int>(centre.y) + radius; ++y)
        for (int x = static_cast<int>(centre.x) - radius; x <= static_cast<int>(centre.x) + radius; ++x) {
            const std::size_t p = 4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                                       static_cast<std::size_t>(x));
            sum += 0.2126 * image.rgba[p] + 0.7152 * image.rgba[p + 1] + 0.0722 * image.rgba[p + 2];
            ++count;
        }
    return sum / count;
}

// Mean irradiance (green) of the receiver texels within [rMin, rMax) of the
// point below the sphere, and the mean the light alone would give there:
// E = Φ/(4π)·h/(h² + r²)^{3/2}, the light h = 1.78 m above the floor.
struct RingAverage {
    double measured = 0.0;
    double unobstructed = 0.0;
};

RingAverage ringIrradiance(const std::vector<float>& map, const ReceiverDesc& receiver, double rMin, double rMax) {
    constexpr double kPower = 30.0, kHeight = 1.78;
    RingAverage ring;
    int count = 0;
    for (int j = 0; j < receiver.resolution; ++j)
        for (int i = 0; i < receiver.resolution; ++i) {
            const double u = ((i + 0.5) / receiver.resolution - 0.5) * receiver.size;
            const double v = ((j + 0.5) / receiver.resolution - 0.5) * receiver.size;
            const double r = std::hypot(u, v);
            if (r < rMin || r >= rMax) continue;
            ring.measured += map[static_cast<std::size_t>(3 * (j * receiver.resolution + i) + 1)];
            ring.unobstructed += kPower / (4.0 * M_PI) * kHeight / std::pow(kHeight * kHeight + r * r, 1.5);
            ++count;
        }
    ring.measured /= count;
    ring.unobstructed /= count;
    return ring;
}

class DefaultRender : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        test::glContext();
        scene_ = new Scene(reducedDefaultScene());
        const FieldSet fields = sim::voxelizeScene(*scene_);
        render::FrameRenderer renderer(*scene_, fields);
        result_ = new render::FrameResult(renderer.render(fields));
        map_ = new std::vector<float>(renderer.receivers().download(0));
    }
    static void TearDownTestSuite() {
        delete scene_;
        delete result_;
        delete map_;
    }
    static Scene* scene_;
    static render::FrameResult* result_;
    static std::vector<float>* map_;
};
Scene* DefaultRender::scene_ = nullptr;
render::FrameResult* DefaultRender::result_ = nullptr;
std::vector<float>* DefaultRender::map_ = nullptr;

// The sphere (R = 0.25 m, n = 1.5) images the light about 0.53 m below its
// centre, i.e. onto the floor: irradiance within 4 cm of the axis must exceed
// that of the directly lit floor (0.75–0.9 m out, beyond the shadow and the
// halo of the smoothed interface) by 3×; that floor itself must follow the
// inverse-square law within 3%.
TEST_F(DefaultRender, CausticOnFloorIsThreeTimesDirectLight) {
    const RingAverage caustic = ringIrradiance(*map_, scene_->receivers[0], 0.0, 0.04);
    const RingAverage direct = ringIrradiance(*map_, scene_->receivers[0], 0.75, 0.9);
    test::reportFigure("default_direct_floor_over_inverse_square", direct.measured / direct.unobstructed);
    test::reportFigure("default_caustic_over_direct", caustic.measured / direct.measured);
    EXPECT_NEAR(direct.measured / direct.unobstructed, 1.0, 0.03);
    EXPECT_GT(caustic.measured, 3.0 * direct.measured);
}

// In the picture: the caustic under the sphere is brighter than the lit
// floor beside it by 1.5× in 8-bit luminance, and the image is not blank.
TEST_F(DefaultRender, PictureShowsCausticAndIsNotBlank) {
    const render::Image8& image = result_->image;
    ASSERT_EQ(image.width, 200);
    const double caustic = meanLuminance(image, projectToPixel(*scene_, {0.0, 0.02, 0.0}), 1);
    const double floor = meanLuminance(image, projectToPixel(*scene_, {0.75, 0.02, 0.5}), 2);
    test::reportFigure("default_picture_caustic_over_floor_luminance", caustic / floor);
    EXPECT_GT(floor, 40.0) << "the directly lit floor is visible";
    EXPECT_GT(caustic, 1.5 * floor);

    double sum = 0.0, sumSquares = 0.0;
    for (std::size_t p = 0; p < image.rgba.size(); p += 4) {
        sum += image.rgba[p + 1];
        sumSquares += static_cast<double>(image.rgba[p + 1]) * image.rgba[p + 1];
    }
    const double pixels = static_cast<double>(image.rgba.size() / 4);
    const double deviation = std::sqrt(sumSquares / pixels - std::pow(sum / pixels, 2));
    EXPECT_GT(deviation, 20.0) << "an image with this little contrast is blank";
}

// Its medium is uniform air (the sphere is analytic): prepare and the step
// structure are written in closed form, not run (render/graph/UniformMedium.h).
TEST_F(DefaultRender, ReportsEveryStageAndBalancesEnergy) {
    std::vector<std::string> names;
    for (const auto& stage : result_->stages) {
        names.push_back(stage.name);
        const bool closedForm = stage.name == "prepare" || stage.name == "step_structure";
        EXPECT_EQ(stage.ran, !closedForm) << stage.name << " on the first frame";
        EXPECT_EQ(stage.skippedBecause.empty(), !closedForm) << stage.name << ": " << stage.skippedBecause;
    }
    EXPECT_EQ(names, (std::vector<std::string>{"upload", "prepare", "step_structure", "photons", "view", "post"}));
    EXPECT_LT(result_->photons.balanceError(), 1e-6);
    EXPECT_GT(result_->copied.host, 0u);
}

}  // namespace
}  // namespace eikon
