#include "bridge/grid/GridSpec.h"

#include <algorithm>

namespace eikon {

glm::dvec3 GridSpec::voxelSize() const { return extent() / glm::dvec3(resolution); }

double GridSpec::voxelVolume() const {
    const glm::dvec3 h = voxelSize();
    return h.x * h.y * h.z;
}

double GridSpec::smallestVoxelEdge() const {
    const glm::dvec3 h = voxelSize();
    return std::min({h.x, h.y, h.z});
}

std::size_t GridSpec::cellCount() const {
    return static_cast<std::size_t>(resolution.x) * static_cast<std::size_t>(resolution.y) *
           static_cast<std::size_t>(resolution.z);
}

std::size_t GridSpec::linearIndex(int i, int j, int k) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(resolution.x) *
               (static_cast<std::size_t>(j) + static_cast<std::size_t>(resolution.y) * static_cast<std::size_t>(k));
}

glm::dvec3 GridSpec::cellCentre(int i, int j, int k) const {
    return boundsMin + (glm::dvec3(i, j, k) + 0.5) * voxelSize();
}

bool GridSpec::contains(const glm::dvec3& point) const {
    return point.x >= boundsMin.x && point.y >= boundsMin.y && point.z >= boundsMin.z && point.x <= boundsMax.x &&
           point.y <= boundsMax.y && point.z <= boundsMax.z;
}

}  // namespace eikon
