#include "sim/voxelize/MeshCoverage.h"

#include "bridge/core/Error.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/MeshToVolume.h>
#include <tbb/parallel_for.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <chrono>
#include <mutex>

namespace eikon::sim {

namespace {

void initializeOpenVdbOnce() {
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
}

}  // namespace

MeshCoverage::MeshCoverage(const GridSpec& grid) : grid_(grid), coverage_(grid.cellCount(), 0.0f) {
    initializeOpenVdbOnce();
}

CellBox MeshCoverage::update(const TriangleMesh& mesh) {
    EIKON_CHECK(!mesh.triangles.empty());
    const CellBox region = movedRegion(mesh);
    levelSetMs_ = coverageMs_ = 0.0;
    if (!region.empty()) recompute(mesh, region);
    lastRecomputed_ = region.cellCount();
    previous_ = mesh;
    first_ = false;
    return region;
}

double MeshCoverage::coveredVolume() const {
    double sum = 0.0;
    for (float c : coverage_) sum += c;
    return sum * grid_.voxelVolume();
}

// The moved triangles' old and new bounds, widened by the band in which
// coverage depends on them (half a voxel diagonal plus a voxel of slack for
// trilinear reconstruction of φ).
CellBox MeshCoverage::movedRegion(const TriangleMesh& mesh) const {
    const double margin = 0.5 * glm::length(grid_.voxelSize()) + grid_.smallestVoxelEdge();
    glm::dvec3 lo, hi;
    if (first_ || previous_.vertices.size() != mesh.vertices.size() || previous_.triangles != mesh.triangles) {
        vertexBounds(mesh, lo, hi);
        CellBox box = CellBox::around(grid_, lo, hi, margin);
        if (!first_) {
            vertexBounds(previous_, lo, hi);
            box = box.merged(CellBox::around(grid_, lo, hi, margin));
        }
        return box;
    }
    lo = glm::dvec3(std::numeric_limits<double>::infinity());
    hi = -lo;
    for (const glm::ivec3& t : mesh.triangles) {
        bool moved = false;
        for (int c = 0; c < 3; ++c) moved = moved || mesh.vertices[t[c]] != previous_.vertices[t[c]];
        if (!moved) continue;
        for (int c = 0; c < 3; ++c) {
            lo = glm::min(lo, glm::min(mesh.vertices[t[c]], previous_.vertices[t[c]]));
            hi = glm::max(hi, glm::max(mesh.vertices[t[c]], previous_.vertices[t[c]]));
        }
    }
    return CellBox::around(grid_, lo, hi, margin);
}

void MeshCoverage::recompute(const TriangleMesh& mesh, const CellBox& region) {
    const double h = grid_.smallestVoxelEdge();
    const glm::dvec3 voxel = grid_.voxelSize();
    const double halfDiagonal = 0.5 * glm::length(voxel);
    // The band must reach past the cells that use the linear model, with
    // the trilinear stencil of their gradient.
    const float halfWidth = static_cast<float>(std::max(2.0, std::ceil(halfDiagonal / h) + 1.0));

    std::vector<openvdb::Vec3s> points(mesh.vertices.size());
    for (std::size_t v = 0; v < points.size(); ++v)
        points[v] = openvdb::Vec3s(static_cast<float>(mesh.vertices[v].x), static_cast<float>(mesh.vertices[v].y),
                                   static_cast<float>(mesh.vertices[v].z));
    std::vector<openvdb::Vec3I> triangles(mesh.triangles.size());
    for (std::size_t t = 0; t < triangles.size(); ++t)
        triangles[t] = openvdb::Vec3I(mesh.triangles[t].x, mesh.triangles[t].y, mesh.triangles[t].z);
    const openvdb::math::Transform::Ptr transform = openvdb::math::Transform::createLinearTransform(h);
    auto start = std::chrono::steady_clock::now();
    const openvdb::FloatGrid::Ptr distance =
        openvdb::tools::meshToLevelSet<openvdb::FloatGrid>(*transform, points, triangles, halfWidth);

    levelSetMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    start = std::chrono::steady_clock::now();
    const glm::dvec3 step = 0.5 * voxel;
    const double certain = halfDiagonal + 0.5 * h;  // beyond this from the centre φ cannot change sign in the cell
    tbb::parallel_for(region.min.z, region.max.z, [&](int k) {
        openvdb::FloatGrid::ConstAccessor accessor = distance->getConstAccessor();
        const openvdb::tools::GridSampler<openvdb::FloatGrid::ConstAccessor, openvdb::tools::BoxSampler> sampler(
            accessor, distance->transform());
        auto phi = [&](const glm::dvec3& p) { return sampler.wsSample(openvdb::Vec3d(p.x, p.y, p.z)); };
        for (int j = region.min.y; j < region.max.y; ++j)
            for (int i = region.min.x; i < region.max.x; ++i) {
                const glm::dvec3 centre = grid_.cellCentre(i, j, k);
                const double atCentre = phi(centre);
                double value = atCentre >= certain ? 0.0 : 1.0;
                if (std::abs(atCentre) < certain) {
                    // The surface as the plane φ = 0 of φ's local linear model;
                    // the cell's extent along its normal is Σ|n_a|·h_a.
                    glm::dvec3 gradient;
                    for (int axis = 0; axis < 3; ++axis) {
                        glm::dvec3 offset(0.0);
                        offset[axis] = step[axis];
                        gradient[axis] = (phi(centre + offset) - phi(centre - offset)) / voxel[axis];
                    }
                    const double length = glm::length(gradient);
                    const glm::dvec3 normal = length > 0.0 ? gradient / length : glm::dvec3(0, 0, 1);
                    const double width = glm::dot(glm::abs(normal), voxel);
                    value = std::clamp(0.5 - atCentre / (length > 0.0 ? length : 1.0) / width, 0.0, 1.0);
                }
                coverage_[grid_.linearIndex(i, j, k)] = static_cast<float>(value);
            }
    });
    coverageMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace eikon::sim
