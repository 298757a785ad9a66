#include "sim/fluid/MacGrid.h"

#include "sim/fluid/ParallelOps.h"

#include <algorithm>

namespace eikon::sim {

MacGrid::MacGrid(const GridSpec& cells) : grid(cells), h(cells.voxelSize()) {
    for (int axis = 0; axis < 3; ++axis) {
        glm::ivec3 size = grid.resolution;
        size[axis] += 1;
        glm::dvec3 offset(0.5);
        offset[axis] = 0.0;
        velocity[axis] = GridField(size, offset);
    }
}

GridField MacGrid::cellField(double value) const { return GridField(grid.resolution, glm::dvec3(0.5), value); }

double MacGrid::divergence(int i, int j, int k) const {
    return (velocity[0](i + 1, j, k) - velocity[0](i, j, k)) / h.x +
           (velocity[1](i, j + 1, k) - velocity[1](i, j, k)) / h.y +
           (velocity[2](i, j, k + 1) - velocity[2](i, j, k)) / h.z;
}

double MacGrid::maxCellCrossingRate() const {
    double rate = 0.0;
    for (int axis = 0; axis < 3; ++axis) rate = std::max(rate, maxAbs(velocity[axis].values) / h[axis]);
    return rate;
}

}  // namespace eikon::sim
