#include "sim/voxelize/MeshCoverage.h"

#include "bridge/core/Error.h"
#include "sim/voxelize/BandDistance.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/Interpolation.h>
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

CellBlocks MeshCoverage::update(const TriangleMesh& mesh) {
    EIKON_CHECK(!mesh.triangles.empty());
    const CellBlocks region = movedRegion(mesh);
    distanceTriangles_ = 0;
    distanceMs_ = signMs_ = coverageMs_ = 0.0;
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

// The band must reach past the cells that use the linear model, with the
// trilinear stencil of their gradient; in voxels of the smallest edge.
double MeshCoverage::bandHalfWidth() const {
    return std::max(2.0, std::ceil(0.5 * glm::length(grid_.voxelSize()) / grid_.smallestVoxelEdge()) + 1.0);
}

// A cell reads φ at its centre and half a voxel to either side of it.
double MeshCoverage::sampleReach() const {
    const glm::dvec3 voxel = grid_.voxelSize();
    return 0.5 * std::max({voxel.x, voxel.y, voxel.z});
}

// Around each moved triangle, the box of its old and new positions widened
// by the reach of the cells that can see it: a cell reads φ within
// sampleReach() of its centre, trilinearly from distance voxels up to one
// voxel further, and a voxel's distance can come from a triangle up to the
// band's half-width away (its sign changes only where the surface swept
// through it, inside the box). A cell outside every such box reads no value
// the moved triangles decide, so its coverage stands.
CellBlocks MeshCoverage::movedRegion(const TriangleMesh& mesh) const {
    const double h = grid_.smallestVoxelEdge();
    const double margin = sampleReach() + h + bandHalfWidth() * h;
    CellBlocks blocks(grid_);
    auto markTriangle = [&](const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, glm::dvec3 lo, glm::dvec3 hi) {
        lo = glm::min(lo, glm::min(a, glm::min(b, c)));
        hi = glm::max(hi, glm::max(a, glm::max(b, c)));
        blocks.mark(CellBox::around(grid_, lo, hi, margin));
    };
    const bool sameTopology = !first_ && previous_.vertices.size() == mesh.vertices.size() &&
                              previous_.triangles == mesh.triangles;
    if (!sameTopology) {  // a new mesh: everything inside its bounds (and the old one's) may change
        glm::dvec3 lo, hi;
        vertexBounds(mesh, lo, hi);
        blocks.mark(CellBox::around(grid_, lo, hi, margin));
        if (!first_) {
            vertexBounds(previous_, lo, hi);
            blocks.mark(CellBox::around(grid_, lo, hi, margin));
        }
        return blocks;
    }
    for (const glm::ivec3& t : mesh.triangles) {
        const glm::dvec3 &a = mesh.vertices[t.x], &b = mesh.vertices[t.y], &c = mesh.vertices[t.z];
        const glm::dvec3 &pa = previous_.vertices[t.x], &pb = previous_.vertices[t.y], &pc = previous_.vertices[t.z];
        if (a == pa && b == pb && c == pc) continue;
        markTriangle(a, b, c, glm::min(pa, glm::min(pb, pc)), glm::max(pa, glm::max(pb, pc)));
    }
    return blocks;
}

void MeshCoverage::recompute(const TriangleMesh& mesh, const CellBlocks& region) {
    const double h = grid_.smallestVoxelEdge();
    const glm::dvec3 voxel = grid_.voxelSize();
    const double halfDiagonal = 0.5 * glm::length(voxel);
    BandDistanceReport report;
    const openvdb::FloatGrid::Ptr distance =
        bandSignedDistance(mesh, grid_, region, sampleReach(), static_cast<float>(bandHalfWidth()), report);
    distanceTriangles_ = report.triangles;
    distanceMs_ = report.distanceMs;
    signMs_ = report.signMs;

    const std::vector<CellBox> boxes = region.boxes();
    const auto start = std::chrono::steady_clock::now();
    const glm::dvec3 step = 0.5 * voxel;
    const double certain = halfDiagonal + 0.5 * h;  // beyond this from the centre φ cannot change sign in the cell
    tbb::parallel_for(std::size_t{0}, boxes.size(), [&](std::size_t b) {
        const CellBox& box = boxes[b];
        openvdb::FloatGrid::ConstAccessor accessor = distance->getConstAccessor();
        const openvdb::tools::GridSampler<openvdb::FloatGrid::ConstAccessor, openvdb::tools::BoxSampler> sampler(
            accessor, distance->transform());
        auto phi = [&](const glm::dvec3& p) { return sampler.wsSample(openvdb::Vec3d(p.x, p.y, p.z)); };
        for (int k = box.min.z; k < box.max.z; ++k)
            for (int j = box.min.y; j < box.max.y; ++j)
                for (int i = box.min.x; i < box.max.x; ++i) {
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
