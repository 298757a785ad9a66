#include "sim/voxelize/HeightFieldCoverage.h"

#include "bridge/core/Error.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace eikon::sim {

namespace {

// The fraction of [centre − width/2, centre + width/2] inside [low, high].
double overlap(double centre, double width, double low, double high) {
    const double a = std::max(centre - 0.5 * width, low);
    const double b = std::min(centre + 0.5 * width, high);
    return std::max(b - a, 0.0) / width;
}

}  // namespace

HeightField::Sample HeightField::sample(double x, double z) const {
    const double dx = (basinMax.x - basinMin.x) / (nodes.x - 1);
    const double dz = (basinMax.z - basinMin.z) / (nodes.y - 1);
    const double gx = std::clamp((x - basinMin.x) / dx, 0.0, static_cast<double>(nodes.x - 1));
    const double gz = std::clamp((z - basinMin.z) / dz, 0.0, static_cast<double>(nodes.y - 1));
    const int i = std::min(static_cast<int>(gx), nodes.x - 2);
    const int k = std::min(static_cast<int>(gz), nodes.y - 2);
    const double u = gx - i, v = gz - k;
    const double h00 = height(i, k), h10 = height(i + 1, k), h01 = height(i, k + 1), h11 = height(i + 1, k + 1);
    // WaterSurface::mesh's triangles: (i,k)(i,k+1)(i+1,k+1) where v ≥ u, (i,k)(i+1,k+1)(i+1,k) below.
    if (v >= u) return {h00 + u * (h11 - h01) + v * (h01 - h00), (h11 - h01) / dx, (h01 - h00) / dz};
    return {h00 + u * (h10 - h00) + v * (h11 - h10), (h10 - h00) / dx, (h11 - h10) / dz};
}

HeightFieldCoverage::HeightFieldCoverage(const GridSpec& grid)
    : grid_(grid), coverage_(grid.cellCount(), 0.0f) {}

CellBox HeightFieldCoverage::band(const HeightField& water) const {
    const auto [low, high] = std::minmax_element(water.heights->begin(), water.heights->end());
    // A cell is cut where its centre lies within half its width across the
    // plane, w/2 = (|Hx|·hx + hy + |Hz|·hz)/2; every triangle's slopes are
    // node differences along x and z, so the steepest of those bounds them.
    double slope = 0.0;
    const double dx = (water.basinMax.x - water.basinMin.x) / (water.nodes.x - 1);
    const double dz = (water.basinMax.z - water.basinMin.z) / (water.nodes.y - 1);
    for (int k = 0; k < water.nodes.y; ++k)
        for (int i = 0; i < water.nodes.x; ++i) {
            if (i + 1 < water.nodes.x) slope = std::max(slope, std::abs(water.height(i + 1, k) - water.height(i, k)) / dx);
            if (k + 1 < water.nodes.y) slope = std::max(slope, std::abs(water.height(i, k + 1) - water.height(i, k)) / dz);
        }
    const glm::dvec3 h = grid_.voxelSize();
    const double reach = 0.5 * (slope * (h.x + h.z) + h.y) + 0.5 * h.y;
    const double rest = water.basinMax.y;
    return CellBox::around(grid_, glm::dvec3(water.basinMin.x, rest + *low, water.basinMin.z),
                           glm::dvec3(water.basinMax.x, rest + *high, water.basinMax.z), reach);
}

void HeightFieldCoverage::recompute(const HeightField& water, const CellBox& cells) {
    const glm::dvec3 h = grid_.voxelSize();
    tbb::parallel_for(cells.min.z, cells.max.z, [&](int k) {
        for (int j = cells.min.y; j < cells.max.y; ++j)
            for (int i = cells.min.x; i < cells.max.x; ++i) {
                const glm::dvec3 c = grid_.cellCentre(i, j, k);
                const double walls = overlap(c.x, h.x, water.basinMin.x, water.basinMax.x) *
                                     overlap(c.z, h.z, water.basinMin.z, water.basinMax.z);
                double fraction = 0.0;
                if (walls > 0.0) {
                    const HeightField::Sample s = water.sample(c.x, c.z);
                    const double width = std::abs(s.slopeX) * h.x + h.y + std::abs(s.slopeZ) * h.z;
                    const double below = std::clamp(0.5 - (c.y - (water.basinMax.y + s.height)) / width, 0.0, 1.0);
                    // The water's top within the cell, as a height, clipped by the floor.
                    const double top = c.y - 0.5 * h.y + below * h.y;
                    const double bottom = std::max(c.y - 0.5 * h.y, water.basinMin.y);
                    fraction = walls * std::max(top - bottom, 0.0) / h.y;
                }
                coverage_[grid_.linearIndex(i, j, k)] = static_cast<float>(fraction);
            }
    });
    lastRecomputed_ += cells.cellCount();
}

CellBlocks HeightFieldCoverage::update(const HeightField& water) {
    EIKON_CHECK(water.heights && water.heights->size() == static_cast<std::size_t>(water.nodes.x) * water.nodes.y);
    lastRecomputed_ = 0;
    CellBlocks changed(grid_);
    if (!first_ && *water.heights == lastHeights_) return changed;  // a still surface changes nothing
    lastHeights_ = *water.heights;
    const CellBox now = band(water);
    if (first_) {  // the whole basin, from its floor up to the band's top
        CellBox basin = CellBox::around(grid_, water.basinMin, glm::dvec3(water.basinMax.x, grid_.boundsMax.y, water.basinMax.z),
                                        0.5 * std::max({grid_.voxelSize().x, grid_.voxelSize().y, grid_.voxelSize().z}));
        recompute(water, basin);
        changed.mark(basin);
        first_ = false;
    } else {
        for (const CellBox& box : {lastBand_, now}) {
            recompute(water, box);
            changed.mark(box);
        }
    }
    lastBand_ = now;
    return changed;
}

}  // namespace eikon::sim
