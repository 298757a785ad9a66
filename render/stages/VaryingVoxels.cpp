#include "render/stages/VaryingVoxels.h"

#include <algorithm>

namespace eikon::render {

namespace {

// Widens `box` to hold the voxels of row (j, k) whose `components` floats
// differ from the first voxel's.
void addDifferingRow(VoxelBox& box, const float* row, const float* first, int components, int nx, int j, int k) {
    const auto differs = [&](int i) { return !std::equal(first, first + components, row + i * components); };
    int lowest = 0;
    while (lowest < nx && !differs(lowest)) ++lowest;
    if (lowest == nx) return;
    int highest = nx - 1;
    while (!differs(highest)) --highest;
    box.lowest = glm::min(box.lowest, glm::ivec3(lowest, j, k));
    box.highest = glm::max(box.highest, glm::ivec3(highest, j, k));
}

void addDifferingVoxels(VoxelBox& box, const GridSpec& grid, const float* values, int components) {
    const glm::ivec3 n = grid.resolution;
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            addDifferingRow(box, values + grid.linearIndex(0, j, k) * static_cast<std::size_t>(components), values,
                            components, n.x, j, k);
}

}  // namespace

VaryingVoxels varyingVoxels(const FieldUpload& fields) {
    VaryingVoxels varying;
    const glm::ivec3 whole = fields.grid.resolution - 1;
    const bool onGpuOnly = (fields.deltaIndex.floats && !fields.deltaIndex.host) ||
                           (fields.extinction.floats && !fields.extinction.host);
    if (onGpuOnly) {
        varying.box = {glm::ivec3(0), whole};
        return varying;
    }
    varying.box = {whole + 1, glm::ivec3(-1)};
    if (fields.deltaIndex.floats) {
        varying.uniformDelta = fields.deltaIndex.host[0];
        addDifferingVoxels(varying.box, fields.grid, fields.deltaIndex.host, 1);
    }
    if (fields.extinction.floats) {
        varying.uniformExtinction = {fields.extinction.host[0], fields.extinction.host[1], fields.extinction.host[2]};
        addDifferingVoxels(varying.box, fields.grid, fields.extinction.host, 3);
    }
    return varying;
}

}  // namespace eikon::render
