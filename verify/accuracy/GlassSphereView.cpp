#include "verify/accuracy/GlassSphereView.h"

#include "verify/accuracy/AccuracyCase.h"
#include "verify/accuracy/GlassSphereMap.h"
#include "verify/accuracy/ReceiverCaseScene.h"
#include "verify/reference/PinholeCamera.h"
#include "verify/reference/SphereOptics.h"

#include <glm/geometric.hpp>

namespace eikon::accuracy {

namespace {

constexpr double kHeight = 2.0;     // m: the camera above the centre
constexpr double kFovDeg = 16.0;    // the sphere (7.2° off the axis) fills 90% of the image's half-width
constexpr double kInner = 0.8;      // impact parameters measured below this many radii, as for the photons

}  // namespace

Scene glassSphereViewScene(int pixels) {
    Scene scene = receiverCaseScene(glm::dvec3(-0.35), glm::dvec3(0.35), glm::ivec3(8), 1.0);
    scene.objects = {sharpGlassSphere()};
    scene.camera.position = glm::dvec3(0.0, kHeight, 0.0);
    scene.camera.target = glm::dvec3(0.0);
    scene.camera.up = glm::dvec3(0.0, 0.0, -1.0);
    scene.camera.fovDeg = kFovDeg;
    scene.render.method = RenderDesc::Method::ImageSpace;
    scene.render.width = scene.render.height = pixels;
    return scene;
}

Measurement glassSphereViewError(const Scene& scene, const std::vector<glm::vec4>& exits) {
    const ObjectDesc& glass = scene.objects.front();
    const reference::Sphere sphere{glass.sphere.center, glass.sphere.radius};
    const glm::dvec3 plane(0.0, -glassSphereMapField().paraxialFocusFromCentre(), 0.0), normal(0.0, 1.0, 0.0);
    const int width = scene.render.width, height = scene.render.height;
    std::vector<double> relative;
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) {
            const glm::dvec3 d = reference::pixelDirection(scene.camera, width, height, i, j);
            const auto exact = reference::transitSphere(scene.camera.position, d, sphere, glass.material.index);
            if (!exact || exact->impact >= kInner * sphere.radius) continue;
            const glm::dvec3 drawn = glm::normalize(glm::dvec3(exits[static_cast<std::size_t>(j) * width + i]));
            const glm::dvec3 expected = linePlaneIntersection(exact->exitPoint, exact->exitDirection, plane, normal);
            const glm::dvec3 found = linePlaneIntersection(exact->exitPoint, drawn, plane, normal);
            relative.push_back(glm::length(found - expected) / sphere.radius);
        }
    return {"glass_sphere_reference",
            "image space: each pixel's exit direction against the exact two-interface ray, carried from the exact "
            "exit point to the focal plane, over R (RMS)",
            rms(relative), -1.0, static_cast<int>(relative.size())};
}

}  // namespace eikon::accuracy
