// The image-space method (render.method "image_space"): the camera view's
// two-interface refraction against exact rays, and what it draws.
//
// The reference shares no code with the renderer (verify/reference/
// SphereOptics): each pixel's ray meets the analytic sphere (quadratic),
// refracts by the vector form of Snell's law in double precision, crosses
// the sphere along its chord and refracts out. The image-space view finds
// the same exit in its rasterized surface layers; its direction must lie
// within one pixel's angle of the exact one for at least 95% of the
// sphere's pixels.
#include "io/scene/SceneParser.h"
#include "render/graph/FrameRenderer.h"
#include "render/stages/SurfaceLayers.h"
#include "sim/voxelize/AnalyticVoxelizer.h"
#include "tests/integration/GlTestContext.h"
#include "verify/reference/PinholeCamera.h"
#include "verify/reference/SphereOptics.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
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

TEST(ImageSpace, SphereRefractionIsWithinAPixelOfTheExactTwoInterfaceRay) {
    test::glContext();
    const Scene scene = checkerboardSphere(640, 480);
    const FieldSet fields = sim::voxelizeScene(scene);
    render::FrameRenderer renderer(scene, fields, {.photons = {}, .recordViewExits = true});
    renderer.render(fields);
    ASSERT_NE(renderer.imageSpaceView(), nullptr);
    const std::vector<glm::vec4> exits = renderer.imageSpaceView()->downloadExits();
    const CameraDesc& camera = scene.camera;
    const SphereShape& sphere = scene.objects[0].sphere;
    const double pixelAngle = 2.0 * std::tan(camera.fovDeg * M_PI / 360.0) / scene.render.height;  // at the image centre
    int pixels = 0, within = 0, rim = 0, rimWithin = 0;
    double worst = 0.0, worstRimImpact = 0.0, worstInner = 0.0;
    for (int y = 0; y < scene.render.height; ++y)
        for (int x = 0; x < scene.render.width; ++x) {
            const glm::dvec3 d = reference::pixelDirection(camera, scene.render.width, scene.render.height, x, y);
            const auto exact = reference::transitSphere(camera.position, d, {sphere.center, sphere.radius},
                                                        scene.objects[0].material.index);
            if (!exact) continue;
            const double impact = exact->impact / sphere.radius;
            const glm::vec4& drawn = exits[static_cast<std::size_t>(y) * scene.render.width + x];
            const double cosine = std::clamp(glm::dot(glm::normalize(glm::dvec3(drawn)), exact->exitDirection), -1.0, 1.0);
            const double error = std::acos(cosine) / pixelAngle;  // in pixels
            ++pixels;
            within += error <= 1.0;
            worst = std::max(worst, error);
            if (impact > 0.95) {  // the silhouette's ring
                ++rim;
                rimWithin += error <= 1.0;
                if (error >= worst) worstRimImpact = impact;
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

// A scene of the given sharp objects (a JSON list) in image space.
Scene surfacesScene(const std::string& name, const std::string& objects) {
    const std::string path = ::testing::TempDir() + name + ".json";
    std::ofstream(path) << R"({
      "grid": {"resolution": [16, 16, 16], "bounds": {"min": [-1, -0.5, -1], "max": [1, 1.5, 1]}},
      "objects": )" + objects + R"(,
      "lights": [{"type": "point", "position": [0.0, 2.0, 0.0], "power": 10}],
      "camera": {"position": [0.0, 0.5, 2.0], "target": [0.0, 0.5, 0.0], "up": [0, 1, 0], "fov_deg": 40},
      "render": {"method": "image_space", "width": 32, "height": 24}
    })";
    return loadSceneFile(path);
}

render::Viewpoint viewpointAt(const glm::vec3& eye, bool orthographic = false) {
    render::Viewpoint view;
    view.eye = eye;
    view.axis = glm::vec3(0.0f, 0.0f, -1.0f);
    view.orthographic = orthographic;
    return view;
}

// The layers keep only the faces toward a viewpoint (near) and away from it
// (far) where that leaves them the same: surfaces that are all spheres,
// boxes and water, apart, seen from outside every one. From inside a box
// its nearest face turns away from the eye; a sphere inside a box puts two
// faces toward the eye on one ray; an imported mesh winds as its author
// chose.
TEST(ImageSpace, DrawsFacingFacesOnlyWhereTheLayersStayTheSame) {
    test::glContext();
    const std::string sphere = R"({"type": "sphere", "center": [0.0, 0.5, 0.0], "radius": 0.25, "index": 1.5})";
    const std::string box = R"({"type": "box", "min": [0.5, 0.3, -0.2], "max": [0.9, 0.7, 0.2], "index": 1.5})";
    const std::string water =
        R"({"type": "water", "basin": {"min": [-0.9, -0.4, -0.9], "max": [0.9, -0.2, 0.9]}, "cells": [8, 8], "index": 1.333})";
    const render::SurfaceRaster apart(surfacesScene("facing_apart", "[" + sphere + ", " + box + ", " + water + "]"));
    EXPECT_TRUE(apart.drawsFacingFaces(viewpointAt({0.0f, 0.5f, 2.0f})));
    EXPECT_TRUE(apart.drawsFacingFaces(viewpointAt({0.0f, 0.5f, 0.0f}, true)));
    EXPECT_FALSE(apart.drawsFacingFaces(viewpointAt({0.0f, 0.5f, 0.0f})));    // in the sphere
    EXPECT_FALSE(apart.drawsFacingFaces(viewpointAt({0.0f, 0.5f, 0.2502f})));  // between it and its hull
    EXPECT_FALSE(apart.drawsFacingFaces(viewpointAt({0.7f, 0.5f, 0.0f})));    // in the box
    EXPECT_FALSE(apart.drawsFacingFaces(viewpointAt({0.0f, -0.3f, 0.0f})));   // under water
    const std::string outer = R"({"type": "box", "min": [-0.4, 0.0, -0.4], "max": [0.4, 1.0, 0.4], "index": 1.2})";
    const render::SurfaceRaster nested(surfacesScene("facing_nested", "[" + sphere + ", " + outer + "]"));
    EXPECT_FALSE(nested.drawsFacingFaces(viewpointAt({0.0f, 0.5f, 2.0f})));
    const std::string mesh = R"({"type": "mesh", "mesh": {"path": ")" + std::string(EIKON_SOURCE_DIR) +
                             R"(/scenes/meshes/blob.obj", "translate": [0.0, 0.36, 0.0]}, "index": 1.5})";
    const render::SurfaceRaster imported(surfacesScene("facing_mesh", "[" + mesh + "]"));
    EXPECT_FALSE(imported.drawsFacingFaces(viewpointAt({0.0f, 0.5f, 2.0f})));
}

// A glass sphere over a floor receiver, lit by a point light, in image space.
Scene causticScene() {
    const std::string path = ::testing::TempDir() + "image_space_caustic.json";
    std::ofstream(path) << R"({
      "grid": {"resolution": [16, 16, 16], "bounds": {"min": [-0.5, 0.2, -0.5], "max": [0.5, 0.8, 0.5]}},
      "objects": [{"type": "sphere", "center": [0.0, 0.5, 0.0], "radius": 0.25, "index": 1.5}],
      "lights": [{"type": "point", "position": [0.0, 2.0, 0.0], "power": 10}],
      "receivers": [{"type": "plane", "point": [0.0, 0.0, 0.0], "normal": [0, 1, 0], "size": 2.0, "resolution": 64}],
      "camera": {"position": [0.0, 1.0, 2.0], "target": [0.0, 0.3, 0.0], "up": [0, 1, 0], "fov_deg": 40},
      "render": {"method": "image_space", "width": 32, "height": 24, "caustic_map_texels": 64}
    })";
    return loadSceneFile(path);
}

// The frames of one temporal mean draw the lights' layers once; a light
// that moves within the mean has its layers drawn again, so its caustic is
// the one a renderer that began with the light there draws.
TEST(ImageSpace, AMovedLightRedrawsItsLayersWithinATemporalMean) {
    test::glContext();
    const Scene scene = causticScene();
    const FieldSet fields = sim::voxelizeScene(scene);
    render::FrameRenderer renderer(scene, fields, {.photons = {}});
    renderer.render(fields);
    renderer.render(fields);  // the mean's second frame: the layers as they were
    const std::vector<float> before = renderer.receivers().download(0);
    LightDesc moved = scene.lights[0];
    moved.position = glm::dvec3(0.4, 2.0, 0.1);
    renderer.setLight(0, moved);
    renderer.render(fields);
    const std::vector<float> after = renderer.receivers().download(0);

    Scene movedScene = scene;
    movedScene.lights[0] = moved;
    render::FrameRenderer fresh(movedScene, fields, {.photons = {}});
    fresh.render(fields);
    EXPECT_EQ(after, fresh.receivers().download(0));
    EXPECT_NE(after, before);
}

}  // namespace
}  // namespace eikon
