// Keyed poses and amounts over time (bridge/scene/MeshObjectDesc.h):
// linear interpolation between keys, held before the first and after the last.
#pragma once

#include "bridge/scene/MeshObjectDesc.h"

#include <glm/mat4x4.hpp>

#include <vector>

namespace eikon::sim {

Placement poseAt(const std::vector<PoseKey>& keys, double time);    // identity pose when there are no keys
double amountAt(const std::vector<AmountKey>& keys, double time);   // 0 when there are no keys

// Scale, then rotate about x, y, z (degrees), then translate.
glm::dmat4 placementMatrix(const Placement& placement);

}  // namespace eikon::sim
