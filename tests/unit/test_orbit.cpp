#include "bridge/scene/Orbit.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

namespace eikon {
namespace {

TEST(Orbit, RoundTripsACamera) {
    CameraDesc camera;
    camera.position = glm::dvec3(1.0, 2.0, 3.0);
    camera.target = glm::dvec3(0.5, 0.0, -1.0);
    camera.fovDeg = 33.0;
    const CameraDesc back = cameraOn(orbitOf(camera), camera);
    EXPECT_NEAR(glm::length(back.position - camera.position), 0.0, 1e-12);
    EXPECT_EQ(back.target, camera.target);
    EXPECT_EQ(back.fovDeg, 33.0);
}

TEST(Orbit, AzimuthTurnsAboutUpAndKeepsDistance) {
    Orbit orbit{glm::dvec3(0.0), 2.0, 90.0, 0.0};
    const CameraDesc camera = cameraOn(orbit, CameraDesc{});
    EXPECT_NEAR(camera.position.x, 2.0, 1e-12);
    EXPECT_NEAR(camera.position.z, 0.0, 1e-12);
    orbit.elevationDeg = 95.0;  // clamped short of the pole, where +y up would be parallel to the view
    EXPECT_LT(cameraOn(orbit, CameraDesc{}).position.y, 2.0);
}

}  // namespace
}  // namespace eikon
