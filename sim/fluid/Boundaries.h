// Where the fluid may go: the six faces of the solver box (closed walls or
// open to a still exterior at pressure 0) and a per-cell solid mask (static
// obstacles; any voxelizer may fill it). [Bridson15] §5.1: fluid faces
// that touch a solid or a closed wall carry the solid's (zero) normal velocity.
#pragma once

#include "bridge/scene/Scene.h"
#include "sim/fluid/MacGrid.h"

#include <array>
#include <cstdint>
#include <vector>

namespace eikon::sim {

// Face order of SimDesc::boundaries: x min, x max, y min, y max, z min, z max.
constexpr int faceIndex(int axis, int side) { return 2 * axis + side; }

struct FluidDomain {
    glm::ivec3 cells{1};
    std::array<SimDesc::Boundary, 6> boundaries{};
    std::vector<std::uint8_t> solid;  // one per cell, 1 = solid

    FluidDomain(glm::ivec3 cellCount, const std::array<SimDesc::Boundary, 6>& faces);

    std::size_t cellIndex(int i, int j, int k) const {
        return static_cast<std::size_t>(i) +
               static_cast<std::size_t>(cells.x) *
                   (static_cast<std::size_t>(j) + static_cast<std::size_t>(cells.y) * static_cast<std::size_t>(k));
    }
    bool isSolid(int i, int j, int k) const { return solid[cellIndex(i, j, k)] != 0; }
    bool isOpen(int axis, int side) const { return boundaries[faceIndex(axis, side)] == SimDesc::Boundary::Open; }
    bool anyOpenFace() const;
    // Per face of the box (faceIndex order), whether it is open.
    std::array<bool, 6> openFaces() const;
    // One byte per cell, 1 where the fluid is (the pressure's unknowns).
    std::vector<std::uint8_t> fluidCells() const;

    // The face of axis `axis` with lattice index (i, j, k), between cells
    // (i, j, k) − e_axis and (i, j, k): true when its velocity is prescribed
    // (zero) because it lies on a closed wall or touches a solid cell.
    // Inline: the projection and the boundary pass ask it for every face.
    bool faceIsFixed(int axis, int i, int j, int k) const {
        glm::ivec3 upper(i, j, k);
        glm::ivec3 lower = upper;
        lower[axis] -= 1;
        if (lower[axis] < 0) return !isOpen(axis, 0) || isSolid(upper.x, upper.y, upper.z);
        if (upper[axis] >= cells[axis]) return !isOpen(axis, 1) || isSolid(lower.x, lower.y, lower.z);
        return isSolid(lower.x, lower.y, lower.z) || isSolid(upper.x, upper.y, upper.z);
    }
};

// Marks the cells whose centres lie inside any of the obstacles as solid.
void addObstacles(FluidDomain& domain, const MacGrid& mac, const std::vector<SimDesc::Obstacle>& obstacles);

// Sets every fixed face velocity to zero (static walls and obstacles).
void enforceVelocityBoundaries(MacGrid& mac, const FluidDomain& domain);

}  // namespace eikon::sim
