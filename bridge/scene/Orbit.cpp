#include "bridge/scene/Orbit.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace eikon {

Orbit orbitOf(const CameraDesc& camera) {
    const glm::dvec3 offset = camera.position - camera.target;
    Orbit orbit;
    orbit.target = camera.target;
    orbit.distance = glm::length(offset);
    orbit.azimuthDeg = glm::degrees(std::atan2(offset.x, offset.z));
    orbit.elevationDeg = glm::degrees(std::asin(std::clamp(offset.y / orbit.distance, -1.0, 1.0)));
    return orbit;
}

CameraDesc cameraOn(const Orbit& orbit, const CameraDesc& base) {
    const double azimuth = glm::radians(orbit.azimuthDeg);
    const double elevation = glm::radians(std::clamp(orbit.elevationDeg, -89.0, 89.0));
    CameraDesc camera = base;
    camera.target = orbit.target;
    camera.position = orbit.target + orbit.distance * glm::dvec3(std::cos(elevation) * std::sin(azimuth),
                                                                 std::sin(elevation),
                                                                 std::cos(elevation) * std::cos(azimuth));
    camera.up = glm::dvec3(0.0, 1.0, 0.0);
    return camera;
}

}  // namespace eikon
