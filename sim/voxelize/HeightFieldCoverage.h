// The fraction of every grid cell inside a water body given as a height
// field — walls and a flat floor, a surface of heights on a node grid —
// computed per cell in closed form, with no mesh and no signed distance:
// the water surface of pool_caustics without OpenVDB.
//
// It is MeshCoverage's model (MeshCoverage.h) with the plane taken from the
// surface itself. The surface is the same piecewise-linear one the water
// mesh draws (WaterSurface::mesh: two triangles per node quad, split along
// the diagonal from (i, k) to (i + 1, k + 1)), so at a cell centre the
// height H and its slope (Hx, Hz) are exact. Across a plane with normal
// n ∝ (−Hx, 1, −Hz), MeshCoverage's box filter
// clamp(1/2 − φ/(|∇φ|·w), 0, 1), w = Σ|n_a|·h_a, becomes
//   clamp(1/2 − (y − H) / (|Hx|·hx + hy + |Hz|·hz), 0, 1),
// the length of n cancelling. The walls and the floor are axis-aligned, so
// their fractions are exact overlaps of the cell with the basin.
#pragma once

#include "bridge/grid/GridSpec.h"
#include "sim/voxelize/CellBlocks.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace eikon::sim {

// A water body: walls at basinMin/basinMax in x and z, the floor at
// basinMin.y, heights above the rest level basinMax.y on nodes spanning
// the basin (x fastest).
struct HeightField {
    glm::dvec3 basinMin{0.0}, basinMax{0.0};
    glm::ivec2 nodes{2};
    const std::vector<double>* heights = nullptr;

    double height(int i, int k) const { return (*heights)[static_cast<std::size_t>(k) * nodes.x + i]; }
    // The surface's height above the rest level and its slope at (x, z),
    // clamped into the basin.
    struct Sample {
        double height, slopeX, slopeZ;
    };
    Sample sample(double x, double z) const;
};

class HeightFieldCoverage {
public:
    explicit HeightFieldCoverage(const GridSpec& grid);

    // Brings the coverage up to date with `water` and returns the blocks of
    // cells whose coverage may have changed: on the first call the basin's,
    // later those of the band of rows the surface crosses now or crossed
    // before, or none when no height changed. The walls and floor must stay
    // where they were.
    CellBlocks update(const HeightField& water);

    const std::vector<float>& values() const { return coverage_; }  // one per cell, in [0, 1]
    long long lastRecomputedCells() const { return lastRecomputed_; }

private:
    // The rows of cells whose vertical extent the surface may cross.
    CellBox band(const HeightField& water) const;
    void recompute(const HeightField& water, const CellBox& cells);

    GridSpec grid_;
    std::vector<float> coverage_;
    CellBox lastBand_;
    std::vector<double> lastHeights_;
    bool first_ = true;
    long long lastRecomputed_ = 0;
};

}  // namespace eikon::sim
