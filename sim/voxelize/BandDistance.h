// The narrow-band signed distance φ of a closed triangle mesh, computed only
// where a region of grid cells will read it, so that a local change of the
// mesh costs in proportion to the change and not to the mesh.
//
// φ lives on OpenVDB voxels: cubes of the grid's smallest edge h, voxel
// (i, j, k) at world (i, j, k)·h. Its magnitude is OpenVDB's unsigned
// distance (meshToVolume with UNSIGNED_DISTANCE_FIELD, which accepts open
// meshes) of the sub-mesh of triangles near the region: a voxel's distance
// within the band comes from the triangles within a few voxels of it, so the
// sub-mesh gives the very values the whole mesh would. Its sign is not
// OpenVDB's flood fill of the whole band (which needs the whole surface) but
// ray parity of the whole mesh along VDB rows (RowParity), evaluated only on
// the rows through the region.
#pragma once

#include "bridge/grid/GridSpec.h"
#include "bridge/mesh/TriangleMesh.h"
#include "sim/voxelize/CellBlocks.h"

#include <openvdb/openvdb.h>

#include <cstddef>

namespace eikon::sim {

struct BandDistanceReport {
    std::size_t triangles = 0;  // in the sub-mesh whose distance was computed
    double distanceMs = 0.0;    // choosing the sub-mesh and its unsigned distance
    double signMs = 0.0;        // binning the whole mesh onto rows and signing the region's voxels
};

// φ in metres (negative inside, |φ| ≤ halfWidth·h, ±halfWidth·h beyond the
// band) at every voxel that trilinear sampling reads at points within
// `reach` metres (on each axis) of the centre of a cell of `region`. Voxels
// outside that reach may hold unsigned or no values. `mesh` must be closed.
openvdb::FloatGrid::Ptr bandSignedDistance(const TriangleMesh& mesh, const GridSpec& grid, const CellBlocks& region,
                                           double reach, float halfWidth, BandDistanceReport& report);

}  // namespace eikon::sim
