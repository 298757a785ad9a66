// A box of grid cells, [min, max) on each axis: the region of a grid that a
// frame's change touched, which must be recomputed (sim/voxelize) and copied
// to the GPU again (FieldSet's changes).
#pragma once

#include "bridge/grid/GridSpec.h"

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace eikon {

struct CellBox {
    glm::ivec3 min{0};
    glm::ivec3 max{0};  // exclusive

    bool empty() const { return max.x <= min.x || max.y <= min.y || max.z <= min.z; }
    long long cellCount() const {
        return empty() ? 0 : static_cast<long long>(max.x - min.x) * (max.y - min.y) * (max.z - min.z);
    }
    static CellBox whole(const GridSpec& grid) { return {glm::ivec3(0), grid.resolution}; }
    // The smallest box holding both (an empty one adds nothing).
    CellBox unite(const CellBox& other) const {
        if (other.empty()) return *this;
        if (empty()) return other;
        return {glm::min(min, other.min), glm::max(max, other.max)};
    }

    // Cells whose centres may lie within `margin` metres of the world box
    // [lo, hi], clipped to the grid.
    static CellBox around(const GridSpec& grid, const glm::dvec3& lo, const glm::dvec3& hi, double margin) {
        const glm::dvec3 h = grid.voxelSize();
        const glm::dvec3 a = (lo - margin - grid.boundsMin) / h - 0.5;
        const glm::dvec3 b = (hi + margin - grid.boundsMin) / h - 0.5;
        CellBox box;
        for (int axis = 0; axis < 3; ++axis) {
            if (!(a[axis] <= b[axis])) return {};  // an empty or non-finite range
            // Clamped in double before the cast: a box far outside the grid
            // (any finite placement) covers no cell, and no int overflows.
            const double cells = static_cast<double>(grid.resolution[axis]);
            const double first = std::ceil(std::clamp(a[axis], -1.0, cells));
            const double last = std::floor(std::clamp(b[axis], -1.0, cells));
            box.min[axis] = static_cast<int>(std::clamp(first, 0.0, cells));
            box.max[axis] = static_cast<int>(std::clamp(last + 1.0, 0.0, cells));
        }
        return box;
    }
};

}  // namespace eikon
