// The image-space method (render.method "image_space"): the camera view's
// two-interface refraction against exact rays, and what it draws.
//
// The reference is computed here, sharing no code with the renderer: each
// pixel's ray meets the analytic sphere (quadratic), refracts by the vector
// form of Snell's law in double precision, crosses the sphere along its
// chord and refracts out. The image-space view finds the same exit in its
// rasterized surface layers; its direction must lie within one pixel's
// angle of the exact one for at least 95% of the sphere's pixels.
#include "io/scene/SceneParser.h"
#include "render/graph/FrameRenderer.h"
#include "sim/voxelize/AnalyticVoxelizer.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

namespace eikon {
namespace {

// A glass sphere over a checkered ground, seen by the camera alone.
Scene checkerboardSphere(int width, int height) {
    const std::string path = ::testing::TempDir() + "image_space_sphere.json";
    std::ofstream(path) << R"({
      "grid": {"resolution": [16, 16, 16], "bounds": {"min": [-0.5, 0.2, -0.5], "max": [0.5, 0.8, 0.5]}},
      "objects": [{"type": "sphere", "center": [0.0, 0.5, 0.0], "radius": 0.25, "index": 1.5}],
      "lights": [{"type": "point", "position": [0.0, 2.0, 0.0], "power": 10}],
      "camera": {"position": [0.3, 0.75, 1.5], "target": [0.0, 0.5, 0.0], "up": [0, 1, 0], "fov_deg": 40},
      "render": {"method": "image_space", "width": )" +
                                std::to_string(width) + R"(, "height": )" + std::to_string(height) + R"(,
                 "environment": {"type": "sky", "ground_height": 0.0, "checker_size": 0.1}}
    })";
    return loadSceneFile(path);
}

glm::dvec3 refracted(const glm::dvec3& d, const glm::dvec3& normal, double eta) {
    const double cosI = -glm::dot(d, normal);
    const double k = 1.0 - eta * eta * (1.0 - cosI * cosI);
    if (k < 0.0) return glm::dvec3(0.0);
    return eta * d + (eta * cosI - std::sqrt(k)) * normal;
}

struct ExactRay {
    glm::dvec3 exit;          // direction after both interfaces
    double impact = 0.0;      // distance of the ray from the centre, in radii
};

// The exact two-interface path of the ray from `origin` along unit `d`, if it meets the sphere.
std::optional<ExactRay> exactRay(const glm::dvec3& origin, const glm::dvec3& d, const SphereShape& sphere, double n) {
    const glm::dvec3 offset = origin - sphere.center;
    const double b = glm::dot(offset, d), c = glm::dot(offset, offset) - sphere.radius * sphere.radius;
    const double discriminant = b * b - c;
    if (discriminant <= 0.0) return std::nullopt;
    const glm::dvec3 entry = origin + (-b - std::sqrt(discriminant)) * d;
    const glm::dvec3 inside = glm::normalize(refracted(d, (entry - sphere.center) / sphere.radius, 1.0 / n));
    const glm::dvec3 exitPoint = entry - 2.0 * glm::dot(entry - sphere.center, inside) * inside;
    const glm::dvec3 out = refracted(inside, -(exitPoint - sphere.center) / sphere.radius, n);
    const double impact = glm::length(glm::cross(offset, d)) / sphere.radius;
    return ExactRay{glm::normalize(out), impact};
}

TEST(ImageSpace, SphereRefractionIsWithinAPixelOfTheExactTwoInterfaceRay) {
    test::glContext();
    const Scene scene = checkerboardSphere(640, 480);
    const FieldSet fields = sim::voxelizeScene(scene);
    render::FrameRenderer renderer(scene, fields, {.photons = {}, .recordViewExits = true});
    renderer.render(fields);
    ASSERT_NE(renderer.imageSpaceView(), nullptr);
    const std::vector<glm::vec4> exits = renderer.imageSpaceView()->downloadExits();
    const CameraDesc& camera = scene.camera;
    const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::dvec3 up = glm::cross(right, forward);
    const double tanHalf = std::tan(camera.fovDeg * M_PI / 360.0);
    const double aspect = static_cast<double>(scene.render.width) / scene.render.height;
    const double pixelAngle = 2.0 * tanHalf / scene.render.height;  // at the image centre
    int pixels = 0, within = 0, rim = 0, rimWithin = 0;
    double worst = 0.0, worstRimImpact = 0.0, worstInner = 0.0;
    for (int y = 0; y < scene.render.height; ++y)
        for (int x = 0; x < scene.render.width; ++x) {
            const double u = ((x + 0.5) / scene.render.width * 2.0 - 1.0) * tanHalf * aspect;
            const double v = ((y + 0.5) / scene.render.height * 2.0 - 1.0) * tanHalf;
            const glm::dvec3 d = glm::normalize(forward + u * right - v * up);
            const auto exact = exactRay(camera.position, d, scene.objects[0].sphere, scene.objects[0].material.index);
            if (!exact) continue;
            const glm::vec4& drawn = exits[static_cast<std::size_t>(y) * scene.render.width + x];
            const double cosine = std::clamp(glm::dot(glm::normalize(glm::dvec3(drawn)), exact->exit), -1.0, 1.0);
            const double error = std::acos(cosine) / pixelAngle;  // in pixels
            ++pixels;
            within += error <= 1.0;
            worst = std::max(worst, error);
            if (exact->impact > 0.95) {  // the silhouette's ring
                ++rim;
                rimWithin += error <= 1.0;
                if (error >= worst) worstRimImpact = exact->impact;
            } else {
                worstInner = std::max(worstInner, error);
            }
        }
    const double fraction = static_cast<double>(within) / pixels;
    test::reportFigure("image_space_sphere_pixels", pixels);
    test::reportFigure("image_space_fraction_within_one_pixel", fraction);
    test::reportFigure("image_space_worst_error_pixels", worst);
    test::reportFigure("image_space_worst_error_inside_0.95_radius_pixels", worstInner);
    test::reportFigure("image_space_rim_fraction_within_one_pixel", static_cast<double>(rimWithin) / rim);
    test::reportFigure("image_space_worst_error_impact_radii", worstRimImpact);
    EXPECT_GT(pixels, 20000);
    EXPECT_GE(fraction, 0.95);
}

}  // namespace
}  // namespace eikon
