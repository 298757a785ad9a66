// The ordinary view through an orthographic camera (camera.projection
// "orthographic"): every ray leaves the image plane along the camera's
// axis, so rays that meet nothing leave as they came, the picture is the
// same from any distance, and it has the scale width_m / width: an
// absorbing sphere (κ, radius R) seen over a uniform background of
// radiance 1 transmits T = exp(−κ·chord), and along the row at height y,
// Σ −ln T · pixel = κ·π·(R² − y²), the area of its slice, whatever the
// voxels do to its outline.
#include "render/graph/FrameRenderer.h"
#include "sim/voxelize/AnalyticVoxelizer.h"
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace eikon {
namespace {

using namespace test;

TEST(OrthographicView, RaysAreParallelAndTheImageKeepsItsSizeWithDistance) {
    glContext();
    const double radius = 0.2, kappa = 20.0, pixel = 0.01;
    Scene scene = emptyScene(glm::dvec3(-0.5), glm::dvec3(0.5), 48);
    ObjectDesc sphere;
    sphere.sphere = {glm::dvec3(0.0), radius};
    sphere.material.extinction = Rgb(kappa);
    sphere.surface = ObjectDesc::Surface::Smooth;
    scene.objects.push_back(sphere);
    scene.lights.push_back(directionalLight({0.0, -1.0, 0.0}, 1.0));
    scene.render.environment.radiance = Rgb(1.0);
    scene.render.width = scene.render.height = 100;
    scene.camera.projection = CameraDesc::Projection::Orthographic;
    scene.camera.widthM = 100 * pixel;
    const FieldSet fields = sim::voxelizeScene(scene);

    std::vector<std::vector<float>> images;
    for (double distance : {2.0, 5.0}) {
        scene.camera.position = glm::dvec3(0.0, 0.0, distance);
        render::FrameRenderer renderer(scene, fields, {.photons = {}, .recordViewExits = true});
        renderer.render(fields);
        images.push_back(renderer.viewStage().downloadHdr());
        const std::vector<glm::vec4> exits = renderer.viewStage().downloadExits();
        double worstTurn = 0.0;
        for (const glm::vec4& exit : exits)
            if (exit.w == 1.0f) worstTurn = std::max(worstTurn, glm::length(glm::dvec3(exit) - glm::dvec3(0, 0, -1)));
        EXPECT_LT(worstTurn, 1e-6) << "from " << distance << " m every escaping ray keeps the camera's axis";
        double opticalDepth = 0.0;
        for (int i = 0; i < scene.render.width; ++i) opticalDepth -= std::log(images.back()[4 * (50 * 100 + i)]);
        const double y = -0.5 * pixel;  // row 50's centre
        const double measured = opticalDepth * pixel / (kappa * std::numbers::pi * (radius * radius - y * y));
        reportFigure(distance == 2.0 ? "orthographic_slice_area_ratio_from_2m" : "orthographic_slice_area_ratio_from_5m",
                     measured);
        EXPECT_NEAR(measured, 1.0, 0.02) << "from " << distance << " m";
    }
    double difference = 0.0;
    for (std::size_t p = 0; p < images[0].size(); ++p)
        difference = std::max(difference, static_cast<double>(std::abs(images[0][p] - images[1][p])));
    EXPECT_LT(difference, 1e-4) << "the same picture from 2 m and 5 m";
}

}  // namespace
}  // namespace eikon
