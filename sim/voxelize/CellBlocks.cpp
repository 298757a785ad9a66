#include "sim/voxelize/CellBlocks.h"

#include "bridge/core/Error.h"

#include <algorithm>

namespace eikon::sim {

CellBlocks::CellBlocks(const GridSpec& grid)
    : resolution_(grid.resolution),
      blocks_((grid.resolution + kEdge - 1) / kEdge),
      marked_(static_cast<std::size_t>(blocks_.x) * blocks_.y * blocks_.z, 0) {}

std::size_t CellBlocks::blockIndex(int i, int j, int k) const {
    return static_cast<std::size_t>(i) + blocks_.x * (static_cast<std::size_t>(j) + blocks_.y * static_cast<std::size_t>(k));
}

void CellBlocks::mark(const CellBox& cells) {
    if (cells.empty()) return;
    const glm::ivec3 first = cells.min / kEdge;
    const glm::ivec3 last = (cells.max - 1) / kEdge;
    for (int k = first.z; k <= last.z; ++k)
        for (int j = first.y; j <= last.y; ++j)
            for (int i = first.x; i <= last.x; ++i) marked_[blockIndex(i, j, k)] = 1;
}

bool CellBlocks::overlaps(const CellBox& cells) const {
    if (cells.empty()) return false;
    const glm::ivec3 first = cells.min / kEdge;
    const glm::ivec3 last = (cells.max - 1) / kEdge;
    for (int k = first.z; k <= last.z; ++k)
        for (int j = first.y; j <= last.y; ++j)
            for (int i = first.x; i <= last.x; ++i)
                if (marked_[blockIndex(i, j, k)]) return true;
    return false;
}

void CellBlocks::add(const CellBlocks& other) {
    EIKON_CHECK_EQ(other.marked_.size(), marked_.size());
    for (std::size_t b = 0; b < marked_.size(); ++b) marked_[b] |= other.marked_[b];
}

bool CellBlocks::empty() const { return std::none_of(marked_.begin(), marked_.end(), [](unsigned char m) { return m; }); }

long long CellBlocks::cellCount() const {
    long long cells = 0;
    for (const CellBox& box : boxes()) cells += box.cellCount();
    return cells;
}

std::vector<CellBox> CellBlocks::boxes() const {
    std::vector<CellBox> result;
    for (int k = 0; k < blocks_.z; ++k)
        for (int j = 0; j < blocks_.y; ++j)
            for (int i = 0; i < blocks_.x; ++i) {
                if (!marked_[blockIndex(i, j, k)]) continue;
                const glm::ivec3 min = glm::ivec3(i, j, k) * kEdge;
                result.push_back({min, glm::min(min + kEdge, resolution_)});
            }
    return result;
}

}  // namespace eikon::sim
