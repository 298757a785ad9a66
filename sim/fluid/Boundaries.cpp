#include "sim/fluid/Boundaries.h"

#include <tbb/parallel_for.h>

#include <glm/geometric.hpp>

#include <algorithm>

namespace eikon::sim {

FluidDomain::FluidDomain(glm::ivec3 cellCount, const std::array<SimDesc::Boundary, 6>& faces)
    : cells(cellCount),
      boundaries(faces),
      solid(static_cast<std::size_t>(cellCount.x) * static_cast<std::size_t>(cellCount.y) *
                static_cast<std::size_t>(cellCount.z),
            0) {}

bool FluidDomain::anyOpenFace() const {
    return std::any_of(boundaries.begin(), boundaries.end(),
                       [](SimDesc::Boundary b) { return b == SimDesc::Boundary::Open; });
}

std::array<bool, 6> FluidDomain::openFaces() const {
    std::array<bool, 6> open{};
    for (int face = 0; face < 6; ++face) open[face] = boundaries[face] == SimDesc::Boundary::Open;
    return open;
}

std::vector<std::uint8_t> FluidDomain::fluidCells() const {
    std::vector<std::uint8_t> fluid(solid.size());
    for (std::size_t c = 0; c < fluid.size(); ++c) fluid[c] = solid[c] ? 0 : 1;
    return fluid;
}

void addObstacles(FluidDomain& domain, const MacGrid& mac, const std::vector<SimDesc::Obstacle>& obstacles) {
    const glm::ivec3 n = domain.cells;
    tbb::parallel_for(0, n.z, [&](int k) {
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i) {
                const glm::dvec3 p = mac.grid.cellCentre(i, j, k);
                for (const auto& obstacle : obstacles) {
                    const bool inside =
                        obstacle.kind == SimDesc::Obstacle::Kind::Box
                            ? glm::all(glm::greaterThanEqual(p, obstacle.box.min)) &&
                                  glm::all(glm::lessThanEqual(p, obstacle.box.max))
                            : glm::length(p - obstacle.sphere.center) <= obstacle.sphere.radius;
                    if (inside) domain.solid[domain.cellIndex(i, j, k)] = 1;
                }
            }
    });
}

void enforceVelocityBoundaries(MacGrid& mac, const FluidDomain& domain) {
    for (int axis = 0; axis < 3; ++axis) {
        GridField& u = mac.velocity[axis];
        tbb::parallel_for(0, u.size.z, [&](int k) {
            for (int j = 0; j < u.size.y; ++j)
                for (int i = 0; i < u.size.x; ++i)
                    if (domain.faceIsFixed(axis, i, j, k)) u(i, j, k) = 0.0;
        });
    }
}

}  // namespace eikon::sim
