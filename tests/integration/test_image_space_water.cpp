// Water bodies in image space (render/stages/WaterHeightFields.h): the
// camera view's two refractions through a rippled water body against rays
// traced through the body's triangles on the CPU.
//
// The reference shares no code with the renderer's height-field walk: each
// pixel's ray meets the body's triangles as the field buffers carry them
// (FieldSet's corners and corner normals, which the eikonal tracer reads
// too) by brute force, Möller–Trumbore in double precision; takes the
// normal interpolated between the corners at the hit; refracts by the
// vector form of Snell's law (verify/reference/SphereOptics); meets the
// triangles again where it leaves (reflected totally at most twice on the
// way), and refracts out. The view seen from above enters through the
// waves and leaves through the flat bottom or, reflected at a wall, through
// another; seen from below it enters through the bottom and leaves through
// the waves, where the exit found on the height field turns the ray most.
// The walk is exact on the triangles, so all but a rounding's worth of
// pixels (one in a thousand) must agree within a pixel: a walk that lost
// the rays leaving through a wall within the waves' slab, 0.4% of them,
// failed here.
#include "bridge/grid/FieldSet.h"
#include "io/scene/SceneParser.h"
#include "render/graph/FrameRenderer.h"
#include "sim/SceneFields.h"
#include "tests/integration/GlTestContext.h"
#include "verify/reference/PinholeCamera.h"
#include "verify/reference/SphereOptics.h"

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

constexpr double kWaterIndex = 1.333;

// A water body rippled to `swell` m (RMS) seen by the camera at `eye`,
// without receivers, and `others`: more objects, each a JSON object
// followed by a comma.
Scene rippledWater(const std::string& name, const std::string& eye, const std::string& others = "",
                   double swell = 0.006) {
    const std::string path = ::testing::TempDir() + name + ".json";
    std::ofstream(path) << R"({
      "grid": {"resolution": [16, 16, 16], "bounds": {"min": [-0.6, -0.4, -0.6], "max": [0.6, 0.6, 0.6]}},
      "objects": [)" + others + R"({"type": "water", "basin": {"min": [-0.5, -0.3, -0.5], "max": [0.5, 0.0, 0.5]}, "cells": [40, 40],
                   "swell": {"amplitude": )" + std::to_string(swell) + R"(, "wavelength": 0.2, "waves": 6, "seed": 3}, "index": 1.333}],
      "lights": [{"type": "point", "position": [0.0, 2.0, 0.0], "power": 10}],
      "camera": {"position": )" + eye + R"(, "target": [0.0, -0.1, 0.0], "up": [0, 0, -1], "fov_deg": 30},
      "render": {"method": "image_space", "width": 160, "height": 120}
    })";
    return loadSceneFile(path);
}

struct TriangleHit {
    double t = 0.0;
    glm::dvec3 normal{0.0};  // interpolated between the corners, unit
};

// The nearest crossing of the triangles beyond tMin (Möller–Trumbore).
std::optional<TriangleHit> nearestTriangle(const std::vector<float>& triangles, const glm::dvec3& origin,
                                           const glm::dvec3& direction, double tMin) {
    std::optional<TriangleHit> nearest;
    for (std::size_t at = 0; at < triangles.size(); at += kSurfaceTriangleFloats) {
        const auto corner = [&](int c) {
            const float* p = &triangles[at + 4 * static_cast<std::size_t>(c)];
            return glm::dvec3(p[0], p[1], p[2]);
        };
        const glm::dvec3 a = corner(0), ab = corner(1) - a, ac = corner(2) - a;
        const glm::dvec3 p = glm::cross(direction, ac);
        const double determinant = glm::dot(ab, p);
        if (std::abs(determinant) < 1e-18) continue;
        const glm::dvec3 s = origin - a;
        const double u = glm::dot(s, p) / determinant;
        if (u < 0.0 || u > 1.0) continue;
        const glm::dvec3 q = glm::cross(s, ab);
        const double v = glm::dot(direction, q) / determinant;
        if (v < 0.0 || u + v > 1.0) continue;
        const double t = glm::dot(ac, q) / determinant;
        if (t <= tMin || (nearest && t >= nearest->t)) continue;
        const glm::dvec3 normal = (1.0 - u - v) * corner(3) + u * corner(4) + v * corner(5);
        nearest = TriangleHit{t, glm::normalize(normal)};
    }
    return nearest;
}

// Where the camera's ray through a pixel leaves the water, refracted in and
// out, totally reflected inside up to twice on the way as the view follows
// it (common/refractor_paths.glsl); none where it misses the water or
// reflects a third time.
std::optional<glm::dvec3> exactExit(const std::vector<float>& triangles, const glm::dvec3& eye, const glm::dvec3& d) {
    const auto entry = nearestTriangle(triangles, eye, d, 0.0);
    if (!entry) return std::nullopt;
    const glm::dvec3 into = glm::dot(entry->normal, d) < 0.0 ? entry->normal : -entry->normal;
    glm::dvec3 inside = reference::crossSurface(d, into, 1.0, kWaterIndex).refracted;
    glm::dvec3 x = eye + entry->t * d;
    for (int leg = 0; leg < 3; ++leg) {
        const auto exit = nearestTriangle(triangles, x, inside, 1e-7);
        if (!exit) return std::nullopt;
        const glm::dvec3 facing = glm::dot(exit->normal, inside) < 0.0 ? exit->normal : -exit->normal;
        const reference::SurfaceCrossing out = reference::crossSurface(inside, facing, kWaterIndex, 1.0);
        if (out.refracted != glm::dvec3(0.0)) return out.refracted;
        x += exit->t * inside;
        inside = out.reflected;
    }
    return std::nullopt;
}

struct ExitAgreement {
    int pixels = 0;
    double withinOnePixel = 0.0;  // fraction
    double worstPixels = 0.0;
};

// Each pixel's exit direction and how it left (ImageSpaceView::downloadExits).
std::vector<glm::vec4> viewExits(const Scene& scene) {
    test::glContext();
    sim::SceneFields sceneFields(scene);
    const FieldSet& fields = sceneFields.fields();
    render::FrameRenderer renderer(scene, fields, {.photons = {}, .recordViewExits = true});
    renderer.render(fields);
    return renderer.imageSpaceView()->downloadExits();
}

ExitAgreement compareExits(const Scene& scene) {
    const std::vector<glm::vec4> exits = viewExits(scene);
    sim::SceneFields sceneFields(scene);
    const FieldSet& fields = sceneFields.fields();
    const CameraDesc& camera = scene.camera;
    const double pixelAngle = 2.0 * std::tan(camera.fovDeg * M_PI / 360.0) / scene.render.height;
    ExitAgreement agreement;
    int within = 0;
    for (int y = 0; y < scene.render.height; ++y)
        for (int x = 0; x < scene.render.width; ++x) {
            const glm::dvec3 d = reference::pixelDirection(camera, scene.render.width, scene.render.height, x, y);
            const auto exact = exactExit(fields.surfaceTriangles, camera.position, d);
            if (!exact) continue;
            const glm::vec4& drawn = exits[static_cast<std::size_t>(y) * scene.render.width + x];
            const double cosine = std::clamp(glm::dot(glm::normalize(glm::dvec3(drawn)), *exact), -1.0, 1.0);
            const double error = drawn.w == 1.0f ? std::acos(cosine) / pixelAngle : 1e9;  // 1: it escaped
            ++agreement.pixels;
            within += error <= 1.0;
            agreement.worstPixels = std::max(agreement.worstPixels, error);
        }
    agreement.withinOnePixel = static_cast<double>(within) / agreement.pixels;
    return agreement;
}

// The view of water rippled to `swell` m from `eye`, whose figures are named after `side`.
void expectExitsMatch(const std::string& side, const std::string& eye, double swell = 0.006) {
    const ExitAgreement agreement = compareExits(rippledWater("water_from_" + side, eye, "", swell));
    const std::string figure = "image_space_water_" + side + "_";
    test::reportFigure((figure + "pixels").c_str(), agreement.pixels);
    test::reportFigure((figure + "fraction_within_one_pixel").c_str(), agreement.withinOnePixel);
    test::reportFigure((figure + "worst_error_pixels").c_str(), agreement.worstPixels);
    EXPECT_GT(agreement.pixels, 10000) << side;
    EXPECT_GE(agreement.withinOnePixel, 0.999) << side;
}

TEST(ImageSpaceWater, RefractionThroughTheWavesMatchesTheTriangles) {
    expectExitsMatch("above", "[0.15, 1.4, 0.6]");
    expectExitsMatch("below", "[0.1, -1.6, 0.3]");
    // Still water: its slab is a plane (the walk once missed it there).
    expectExitsMatch("still", "[0.15, 1.4, 0.6]", 0.0);
}

// A glass box under the water shows through it: its faces are found in
// the layers, where the water's own exit lies farther.
TEST(ImageSpaceWater, ASubmergedBoxShowsThroughTheWater) {
    const std::string eye = "[0.15, 1.4, 0.6]";
    const std::vector<glm::vec4> open = viewExits(rippledWater("water_open", eye));
    const std::vector<glm::vec4> submerged = viewExits(rippledWater(
        "water_submerged", eye, R"({"type": "box", "min": [-0.1, -0.2, -0.1], "max": [0.1, -0.1, 0.1], "index": 1.5},)"));
    ASSERT_EQ(open.size(), submerged.size());
    int turned = 0;
    for (std::size_t i = 0; i < open.size(); ++i)
        turned += glm::dot(glm::normalize(glm::vec3(open[i])), glm::normalize(glm::vec3(submerged[i]))) < 0.9999f;
    test::reportFigure("image_space_water_pixels_turned_by_a_submerged_box", turned);
    EXPECT_GT(turned, 400);  // the box covers about 30 × 25 pixels
}

// Every pixel of pool_caustics, its fifth frame, ends on the pool floor or
// leaves the water after at most two total reflections: none is lost on
// the way (a crossing on a cell's edge, missed between the rounding of the
// two cells' planes, lost 3 of its 307 200 rays).
TEST(ImageSpaceWater, NoRayOfThePoolIsLost) {
    test::glContext();
    Scene scene = loadSceneFile(std::string(EIKON_SOURCE_DIR) + "/scenes/pool_caustics.json");
    scene.render.method = RenderDesc::Method::ImageSpace;
    sim::SceneFields sceneFields(scene);
    for (int frame = 1; frame < 5; ++frame) sceneFields.advanceFrame();
    render::FrameRenderer renderer(scene, sceneFields.fields(), {.photons = {}, .recordViewExits = true});
    renderer.render(sceneFields.fields());
    const std::vector<glm::vec4> exits = renderer.imageSpaceView()->downloadExits();
    const auto lost = std::count_if(exits.begin(), exits.end(), [](const glm::vec4& exit) { return exit.w == 0.0f; });
    const auto onFloor = std::count_if(exits.begin(), exits.end(), [](const glm::vec4& exit) { return exit.w == 2.0f; });
    test::reportFigure("image_space_pool_rays_on_the_floor", static_cast<double>(onFloor));
    EXPECT_EQ(lost, 0);
    EXPECT_GT(onFloor, 200000);  // most of the image is the floor under water
}

}  // namespace
}  // namespace eikon
