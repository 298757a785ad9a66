#include "sim/voxelize/BandDistance.h"

#include "sim/voxelize/RowParity.h"

#include <openvdb/tools/MeshToVolume.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace eikon::sim {

namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The VDB voxels that trilinear sampling reads at points within `reach` of
// the centres of a box's cells, [min, max] inclusive.
struct VoxelRange {
    openvdb::Coord min, max;
};

VoxelRange voxelsRead(const GridSpec& grid, const CellBox& box, double reach, double h) {
    const glm::dvec3 voxel = grid.voxelSize();
    VoxelRange range;
    for (int axis = 0; axis < 3; ++axis) {
        const double lo = grid.boundsMin[axis] + (box.min[axis] + 0.5) * voxel[axis] - reach;
        const double hi = grid.boundsMin[axis] + (box.max[axis] - 0.5) * voxel[axis] + reach;
        range.min[axis] = static_cast<int>(std::floor(lo / h));
        range.max[axis] = static_cast<int>(std::floor(hi / h)) + 1;
    }
    return range;
}

// Negates the voxels of `range` that row parity puts inside; inactive ones
// (beyond the band, holding +background) become −background. Idempotent, so
// ranges may overlap.
void signVoxels(openvdb::FloatGrid& phi, const RowParity& parity, const VoxelRange& range) {
    const float insideBeyondBand = -phi.background();
    openvdb::FloatGrid::Accessor accessor = phi.getAccessor();
    std::vector<double> xs;
    for (int k = range.min.z(); k <= range.max.z(); ++k)
        for (int j = range.min.y(); j <= range.max.y(); ++j) {
            parity.crossings(j, k, xs);
            std::size_t below = 0;
            for (int i = range.min.x(); i <= range.max.x(); ++i) {
                while (below < xs.size() && xs[below] < i) ++below;
                if (below % 2 == 0) continue;  // outside: unsigned distance is φ
                const openvdb::Coord ijk(i, j, k);
                float value;
                if (accessor.probeValue(ijk, value))
                    accessor.setValueOnly(ijk, -std::abs(value));
                else
                    accessor.setValueOff(ijk, insideBeyondBand);
            }
        }
}

}  // namespace

openvdb::FloatGrid::Ptr bandSignedDistance(const TriangleMesh& mesh, const GridSpec& grid, const CellBlocks& region,
                                           double reach, float halfWidth, BandDistanceReport& report) {
    const double h = grid.smallestVoxelEdge();
    auto start = std::chrono::steady_clock::now();

    // The sub-mesh: triangles that can give a voxel read by the region its
    // distance. OpenVDB rasterises a triangle into the voxels within
    // √0.75 + √3 < 3 voxels of it, and each step of its band expansion
    // beyond 2 voxels (two per voxel of band) passes a triangle on to the
    // next voxel; voxels are read up to reach + h from a cell centre.
    const double influence = (3.0 + 2.0 * std::max(0.0, std::ceil(halfWidth) - 2.0)) * h;
    const double margin = reach + h + influence;
    std::vector<openvdb::Vec3s> points(mesh.vertices.size());
    std::vector<glm::dvec3> indexPoints(mesh.vertices.size());
    for (std::size_t v = 0; v < points.size(); ++v) {
        indexPoints[v] = mesh.vertices[v] / h;
        points[v] = openvdb::Vec3s(static_cast<float>(indexPoints[v].x), static_cast<float>(indexPoints[v].y),
                                   static_cast<float>(indexPoints[v].z));
    }
    std::vector<openvdb::Vec3I> nearby;
    for (const glm::ivec3& t : mesh.triangles) {
        const glm::dvec3 &a = mesh.vertices[t.x], &b = mesh.vertices[t.y], &c = mesh.vertices[t.z];
        if (region.overlaps(CellBox::around(grid, glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c)), margin)))
            nearby.emplace_back(t.x, t.y, t.z);
    }
    report.triangles = nearby.size();
    const openvdb::math::Transform::Ptr transform = openvdb::math::Transform::createLinearTransform(h);
    const openvdb::tools::QuadAndTriangleDataAdapter<openvdb::Vec3s, openvdb::Vec3I> subMesh(points, nearby);
    openvdb::FloatGrid::Ptr phi = openvdb::tools::meshToVolume<openvdb::FloatGrid>(
        subMesh, *transform, halfWidth, halfWidth, openvdb::tools::UNSIGNED_DISTANCE_FIELD);
    report.distanceMs = millisecondsSince(start);

    start = std::chrono::steady_clock::now();
    std::vector<VoxelRange> ranges;
    for (const CellBox& box : region.boxes()) ranges.push_back(voxelsRead(grid, box, reach, h));
    if (!ranges.empty()) {
        glm::ivec2 rowMin(ranges[0].min.y(), ranges[0].min.z()), rowMax(ranges[0].max.y(), ranges[0].max.z());
        for (const VoxelRange& range : ranges) {
            rowMin = glm::min(rowMin, glm::ivec2(range.min.y(), range.min.z()));
            rowMax = glm::max(rowMax, glm::ivec2(range.max.y(), range.max.z()));
        }
        const RowParity parity(indexPoints, mesh.triangles, rowMin, rowMax);
        for (const VoxelRange& range : ranges) signVoxels(*phi, parity, range);
    }
    report.signMs = millisecondsSince(start);
    return phi;
}

}  // namespace eikon::sim
