#include "render/stages/DiagnosticNodeSteps.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace eikon::render {

namespace {

constexpr int kBrickLevel = 2;  // log2 of BrickRanges::kVoxels
static_assert(1 << kBrickLevel == BrickRanges::kVoxels);

struct Range {
    glm::vec4 lowest{std::numeric_limits<float>::infinity()};
    glm::vec4 highest{-std::numeric_limits<float>::infinity()};
};

// The range over the bricks [first, last], clamped to the grid's.
Range rangeOver(const BrickRanges& bricks, glm::ivec3 first, glm::ivec3 last) {
    first = glm::max(first, glm::ivec3(0));
    last = glm::min(last, bricks.count - 1);
    Range range;
    for (int k = first.z; k <= last.z; ++k)
        for (int j = first.y; j <= last.y; ++j)
            for (int i = first.x; i <= last.x; ++i) {
                const std::size_t brick = bricks.index({i, j, k});
                range.lowest = glm::min(range.lowest, bricks.lowest[brick]);
                range.highest = glm::max(range.highest, bricks.highest[brick]);
            }
    return range;
}

bool nearlyUniform(const Range& range, float tolerance) {
    const bool sameExtinction = range.lowest.y == range.highest.y && range.lowest.z == range.highest.z &&
                                range.lowest.w == range.highest.w;
    return sameExtinction && range.highest.x - range.lowest.x <= tolerance;
}

}  // namespace

std::vector<float> nearlyUniformNodeLevels(const BrickRanges& bricks, double reachVoxels, double epsilon) {
    std::vector<float> levels(bricks.lowest.size(), 0.0f);
    if (bricks.empty()) return levels;
    const Range whole = rangeOver(bricks, glm::ivec3(0), bricks.count - 1);
    const auto tolerance = static_cast<float>(epsilon * (whole.highest.x - whole.lowest.x));
    const int reach = static_cast<int>(std::ceil(reachVoxels / BrickRanges::kVoxels));
    // From the brick up to the node that holds the whole grid: a node holds
    // its children's grown voxels, so where a node is nearly uniform its
    // children are, and the larger level wins.
    int largestLevel = kBrickLevel;
    const int widest = std::max({bricks.count.x, bricks.count.y, bricks.count.z});
    while ((1 << (largestLevel - kBrickLevel)) < widest) ++largestLevel;
    for (int level = kBrickLevel; level <= largestLevel; ++level) {
        const int span = 1 << (level - kBrickLevel);  // bricks along a node's edge
        const glm::ivec3 nodes = (bricks.count + span - 1) / span;
        for (int k = 0; k < nodes.z; ++k)
            for (int j = 0; j < nodes.y; ++j)
                for (int i = 0; i < nodes.x; ++i) {
                    const glm::ivec3 first = glm::ivec3(i, j, k) * span;
                    const glm::ivec3 last = glm::min(first + span - 1, bricks.count - 1);
                    if (!nearlyUniform(rangeOver(bricks, first - reach, last + reach), tolerance)) continue;
                    for (int z = first.z; z <= last.z; ++z)
                        for (int y = first.y; y <= last.y; ++y)
                            for (int x = first.x; x <= last.x; ++x) levels[bricks.index({x, y, z})] = float(level);
                }
    }
    return levels;
}

}  // namespace eikon::render
