// The camera's ray through a pixel, by the view shaders' pinhole model
// (shaders/view_rays.comp, image_space_view.comp): the vertical field of
// view over the image's height, row 0 at the top. For tests and the
// accuracy cases that compare a view with exact rays.
#pragma once

#include "bridge/scene/Scene.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace eikon::reference {

// Unit direction of the ray through the centre of pixel (i, j) of a
// width × height image.
inline glm::dvec3 pixelDirection(const CameraDesc& camera, int width, int height, int i, int j) {
    const glm::dvec3 forward = glm::normalize(camera.target - camera.position);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
    const glm::dvec3 up = glm::cross(right, forward);
    const double tanHalf = std::tan(glm::radians(camera.fovDeg) / 2.0);
    const double aspect = static_cast<double>(width) / height;
    const double ndcX = (i + 0.5) / width * 2.0 - 1.0;
    const double ndcY = (j + 0.5) / height * 2.0 - 1.0;
    return glm::normalize(forward + ndcX * tanHalf * aspect * right - ndcY * tanHalf * up);
}

}  // namespace eikon::reference
