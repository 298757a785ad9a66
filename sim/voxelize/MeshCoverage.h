// The fraction of every grid cell inside a closed triangle mesh, kept from
// frame to frame so that only the band the mesh moved through is redone.
//
// Sun et al. [Sun08] §4.1 rasterise the mesh at 4× resolution and average
// 4³ samples per voxel wherever a voxel and its neighbours disagree. Here a
// narrow-band signed distance φ on cubes of the grid's smallest edge comes
// from bandSignedDistance (BandDistance.h) for the cells being redone only:
// OpenVDB's unsigned distance of the triangles near them, signed by ray
// parity of the whole mesh (so winding does not matter), so that a local
// change costs in proportion to its size, not the mesh's. A cell whose
// centre is farther than half its diagonal (plus half a voxel of slack)
// from the surface is 0 or 1 outright; a cell the surface may cross takes
// the fraction of a box filter across the plane φ = 0 of φ's local linear
// model: clamp(1/2 − φ/(|∇φ|·w), 0, 1), w = Σ|n_a|·h_a the cell's width
// along the normal n. That is exact for faces parallel to the cell's faces
// and exact on average for planes at any angle, and unlike s³ supersampling
// — which moves in steps of 1/s of a voxel — it follows a surface
// continuously as it moves by a fraction of a voxel: the millimetre ripples
// of a water surface in centimetre voxels are still seen. Volume errors are
// in docs/accuracy.md.
#pragma once

#include "bridge/grid/GridSpec.h"
#include "bridge/mesh/TriangleMesh.h"
#include "sim/voxelize/CellBlocks.h"

#include <cstddef>
#include <vector>

namespace eikon::sim {

class MeshCoverage {
public:
    explicit MeshCoverage(const GridSpec& grid);

    // Brings the coverage up to date with `mesh` (which must be closed) and
    // returns the blocks of cells whose coverage may have changed: on the
    // first call those around the whole mesh, later those around each
    // triangle that moved (its old and new positions plus the band), or none
    // when no vertex moved.
    CellBlocks update(const TriangleMesh& mesh);

    const GridSpec& grid() const { return grid_; }
    const std::vector<float>& values() const { return coverage_; }  // one per cell, in [0, 1]
    // Σ coverage · voxel volume, m³.
    double coveredVolume() const;
    // Cells recomputed by the last update, the triangles whose distance it
    // computed, and its time in ms: the unsigned distance (choosing those
    // triangles, OpenVDB's meshToVolume), its sign (row parity), and the
    // coverage of the recomputed cells.
    long long lastRecomputedCells() const { return lastRecomputed_; }
    std::size_t lastDistanceTriangles() const { return distanceTriangles_; }
    double lastDistanceMilliseconds() const { return distanceMs_; }
    double lastSignMilliseconds() const { return signMs_; }
    double lastCoverageMilliseconds() const { return coverageMs_; }

private:
    double bandHalfWidth() const;  // of the distance band, in voxels of the smallest edge
    double sampleReach() const;    // m
    CellBlocks movedRegion(const TriangleMesh& mesh) const;
    void recompute(const TriangleMesh& mesh, const CellBlocks& region);

    GridSpec grid_;
    std::vector<float> coverage_;
    TriangleMesh previous_;
    bool first_ = true;
    long long lastRecomputed_ = 0;
    std::size_t distanceTriangles_ = 0;
    double distanceMs_ = 0.0;
    double signMs_ = 0.0;
    double coverageMs_ = 0.0;
};

}  // namespace eikon::sim
