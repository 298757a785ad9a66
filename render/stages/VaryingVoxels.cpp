#include "render/stages/VaryingVoxels.h"

#include <glm/common.hpp>

#include <algorithm>
#include <limits>

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

// The ranges of (δn, κ) per brick; a field the scene lacks counts as 0.
BrickRanges brickRanges(const FieldUpload& fields) {
    const glm::ivec3 n = fields.grid.resolution;
    BrickRanges bricks;
    bricks.count = (n + BrickRanges::kVoxels - 1) / BrickRanges::kVoxels;
    const std::size_t count = static_cast<std::size_t>(bricks.count.x) * bricks.count.y * bricks.count.z;
    bricks.lowest.assign(count, glm::vec4(std::numeric_limits<float>::infinity()));
    bricks.highest.assign(count, glm::vec4(-std::numeric_limits<float>::infinity()));
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                const std::size_t voxel = fields.grid.linearIndex(i, j, k);
                glm::vec4 value(0.0f);
                if (fields.deltaIndex.floats) value.x = fields.deltaIndex.host[voxel];
                if (fields.extinction.floats)
                    value = {value.x, fields.extinction.host[3 * voxel], fields.extinction.host[3 * voxel + 1],
                             fields.extinction.host[3 * voxel + 2]};
                const std::size_t brick = bricks.index(glm::ivec3(i, j, k) / BrickRanges::kVoxels);
                bricks.lowest[brick] = glm::min(bricks.lowest[brick], value);
                bricks.highest[brick] = glm::max(bricks.highest[brick], value);
            }
    return bricks;
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
        const float* kappa = fields.extinction.host;
        varying.greyExtinction = true;
        for (std::size_t i = 0; i < fields.grid.cellCount() && varying.greyExtinction; ++i)
            varying.greyExtinction = kappa[3 * i] == kappa[3 * i + 1] && kappa[3 * i] == kappa[3 * i + 2];
        addDifferingVoxels(varying.box, fields.grid, fields.extinction.host, 3);
    }
    varying.bricks = brickRanges(fields);
    return varying;
}

}  // namespace eikon::render
