// The viewer's gestures: orbiting keeps the distance to the target, panning
// moves the point under the cursor with it, zooming scales the distance, and
// dragging a light moves it in its horizontal plane.
#include "apps/viewer/CameraControls.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace eikon::view {
namespace {

CameraDesc camera() {
    CameraDesc c;
    c.position = {0.0, 1.0, 3.0};
    c.target = {0.0, 0.5, 0.0};
    c.up = {0.0, 1.0, 0.0};
    c.fovDeg = 40.0;
    return c;
}

TEST(CameraControls, OrbitKeepsDistanceAndClampsElevation) {
    const Orbit start = orbitOf(camera());
    const Orbit turned = orbitDrag(start, 100.0, 0.0);
    EXPECT_NEAR(turned.azimuthDeg, start.azimuthDeg - 30.0, 1e-12);
    const CameraDesc moved = cameraOn(turned, camera());
    EXPECT_NEAR(glm::length(moved.position - moved.target), start.distance, 1e-12);
    EXPECT_EQ(orbitDrag(start, 0.0, 1e6).elevationDeg, 89.0);
    EXPECT_EQ(orbitDrag(start, 0.0, -1e6).elevationDeg, -89.0);
}

// A drag across the whole viewport height moves the target by the height the
// view spans at the target's distance: 2·d·tan(fov/2).
TEST(CameraControls, PanMovesTheTargetWithTheCursor) {
    const CameraDesc c = camera();
    const Orbit start = orbitOf(c);
    const Orbit panned = panDrag(start, c, 0.0, 600.0, 600);
    const double expected = 2.0 * start.distance * std::tan(glm::radians(20.0));
    EXPECT_NEAR(glm::length(panned.target - start.target), expected, 1e-9);
    EXPECT_GT(panned.target.y, start.target.y);  // dragging down brings the scene down: the target rises
    EXPECT_EQ(panned.distance, start.distance);
}

TEST(CameraControls, ZoomScalesTheDistance) {
    const Orbit start = orbitOf(camera());
    EXPECT_NEAR(zoom(start, 1.0).distance, 0.9 * start.distance, 1e-12);
    EXPECT_NEAR(zoom(zoom(start, 3.0), -3.0).distance, start.distance, 1e-12);
}

TEST(CameraControls, LightDragStaysInItsHorizontalPlane) {
    LightDesc light;
    light.kind = LightDesc::Kind::Point;
    light.position = {0.0, 1.8, 0.0};
    const LightDesc moved = lightDrag(light, camera(), 50.0, -30.0, 600);
    EXPECT_EQ(moved.position.y, light.position.y);
    EXPECT_GT(moved.position.x, light.position.x);  // right on screen: +x for this camera
    EXPECT_LT(moved.position.z, light.position.z);  // up on screen: away from the camera (−z)

    LightDesc sun;
    sun.kind = LightDesc::Kind::Directional;
    sun.direction = glm::normalize(glm::dvec3(0.3, -1.0, 0.0));
    const LightDesc turned = lightDrag(sun, camera(), 40.0, 10.0, 600);
    EXPECT_NEAR(glm::length(turned.direction), 1.0, 1e-12);
    EXPECT_GT(glm::length(turned.direction - sun.direction), 0.1);
}

}  // namespace
}  // namespace eikon::view
