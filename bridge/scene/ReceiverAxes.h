// The axes a receiver's map is laid along: its unit normal and two unit
// tangents, u = normal × (x, or y where the normal is near x) and
// v = normal × u, so that texel (i, j) of the map lies along u and v from the
// square's corner. The renderer's receivers and their exported quads share
// them.
#pragma once

#include "bridge/scene/Scene.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>

namespace eikon {

struct ReceiverAxes {
    glm::dvec3 normal;
    glm::dvec3 u;
    glm::dvec3 v;
};

inline ReceiverAxes receiverAxes(const ReceiverDesc& receiver) {
    const glm::dvec3 normal = glm::normalize(receiver.normal);
    const glm::dvec3 helper = std::abs(normal.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(normal, helper));
    return {normal, u, glm::cross(normal, u)};
}

}  // namespace eikon
