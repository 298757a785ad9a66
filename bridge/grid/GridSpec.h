// The world placement of a dense, cell-centred grid: `resolution` cells over
// the box [boundsMin, boundsMax], cell (i,j,k) centred at
// boundsMin + (i + 1/2, j + 1/2, k + 1/2) · voxelSize. Voxels are boxes; the
// scene format lets them be non-cubic.
#pragma once

#include <glm/vec3.hpp>

#include <cstddef>

namespace eikon {

struct GridSpec {
    glm::ivec3 resolution{1};
    glm::dvec3 boundsMin{0.0};
    glm::dvec3 boundsMax{1.0};

    glm::dvec3 extent() const { return boundsMax - boundsMin; }
    glm::dvec3 voxelSize() const;
    double voxelVolume() const;
    double smallestVoxelEdge() const;
    std::size_t cellCount() const;
    std::size_t linearIndex(int i, int j, int k) const;  // x fastest, then y, then z
    glm::dvec3 cellCentre(int i, int j, int k) const;
    bool contains(const glm::dvec3& point) const;
};

}  // namespace eikon
