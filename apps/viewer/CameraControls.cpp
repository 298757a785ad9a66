#include "apps/viewer/CameraControls.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace eikon::view {

namespace {

constexpr double kDegreesPerPixel = 0.3;

// Metres per pixel at `depth` in front of the camera.
double metresPerPixel(const CameraDesc& camera, double depth, int viewportHeight) {
    return 2.0 * depth * std::tan(glm::radians(camera.fovDeg) / 2.0) / std::max(viewportHeight, 1);
}

glm::dvec3 rotateAbout(const glm::dvec3& v, const glm::dvec3& axis, double radians) {
    return v * std::cos(radians) + glm::cross(axis, v) * std::sin(radians) +
           axis * glm::dot(axis, v) * (1.0 - std::cos(radians));
}

}  // namespace

Orbit orbitDrag(Orbit orbit, double dxPixels, double dyPixels) {
    orbit.azimuthDeg -= kDegreesPerPixel * dxPixels;
    orbit.elevationDeg = std::clamp(orbit.elevationDeg + kDegreesPerPixel * dyPixels, -89.0, 89.0);
    return orbit;
}

Orbit panDrag(Orbit orbit, const CameraDesc& camera, double dxPixels, double dyPixels, int viewportHeight) {
    const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::dvec3 up = glm::cross(right, forward);
    const double scale = metresPerPixel(camera, orbit.distance, viewportHeight);
    orbit.target += scale * (-dxPixels * right + dyPixels * up);
    return orbit;
}

Orbit zoom(Orbit orbit, double notches) {
    orbit.distance *= std::pow(0.9, notches);
    return orbit;
}

LightDesc lightDrag(LightDesc light, const CameraDesc& camera, double dxPixels, double dyPixels, int viewportHeight) {
    const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    if (light.kind == LightDesc::Kind::Directional) {
        glm::dvec3 direction = rotateAbout(light.direction, glm::dvec3(0, 1, 0), glm::radians(kDegreesPerPixel * dxPixels));
        direction = rotateAbout(direction, right, glm::radians(kDegreesPerPixel * dyPixels));
        light.direction = glm::normalize(direction);
        return light;
    }
    glm::dvec3 ahead(forward.x, 0.0, forward.z);
    ahead = glm::length(ahead) > 1e-9 ? glm::normalize(ahead) : glm::dvec3(0, 0, -1);
    const glm::dvec3 side = glm::normalize(glm::dvec3(right.x, 0.0, right.z));
    const double depth = std::max(glm::dot(light.position - camera.position, forward), 1e-3);
    const double scale = metresPerPixel(camera, depth, viewportHeight);
    light.position += scale * (dxPixels * side - dyPixels * ahead);
    return light;
}

}  // namespace eikon::view
