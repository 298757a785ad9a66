// A grid's cells grouped into blocks of 8³: the set of blocks a frame's
// change touched is the region recomputed and repainted. Finer than one
// bounding box: a water surface that moves everywhere marks a thin slab, not
// the whole box down to its floor.
#pragma once

#include "bridge/grid/GridSpec.h"
#include "bridge/grid/CellBox.h"

#include <vector>

namespace eikon::sim {

class CellBlocks {
public:
    static constexpr int kEdge = 8;  // cells per block edge

    explicit CellBlocks(const GridSpec& grid);

    void mark(const CellBox& cells);  // every block the box overlaps
    void add(const CellBlocks& other);  // same grid
    bool empty() const;
    bool overlaps(const CellBox& cells) const;  // true when a block the box overlaps is marked
    long long cellCount() const;
    // The marked blocks as cell boxes, clipped to the grid.
    std::vector<CellBox> boxes() const;

private:
    std::size_t blockIndex(int i, int j, int k) const;

    glm::ivec3 resolution_;
    glm::ivec3 blocks_;
    std::vector<unsigned char> marked_;
};

}  // namespace eikon::sim
