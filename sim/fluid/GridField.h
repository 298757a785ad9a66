// A dense 3D array of doubles sampled on a regular lattice: the cell-centred
// scalars and each staggered velocity component of a MAC grid (Bridson,
// "Fluid Simulation for Computer Graphics", 2nd ed., §2.4) are GridFields that
// differ only in size and in where sample (0, 0, 0) sits.
#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace eikon::sim {

struct GridField {
    glm::ivec3 size{0};
    // Sample (i, j, k) lies at world boundsMin + ((i, j, k) + offset) · h:
    // (½, ½, ½) for cell centres, (0, ½, ½) for x faces, and so on.
    glm::dvec3 offset{0.5};
    std::vector<double> values;

    GridField() = default;
    GridField(glm::ivec3 sampleCount, glm::dvec3 sampleOffset, double value = 0.0);

    std::size_t count() const { return values.size(); }
    std::size_t index(int i, int j, int k) const {
        return static_cast<std::size_t>(i) +
               static_cast<std::size_t>(size.x) *
                   (static_cast<std::size_t>(j) + static_cast<std::size_t>(size.y) * static_cast<std::size_t>(k));
    }
    double& operator()(int i, int j, int k) { return values[index(i, j, k)]; }
    double operator()(int i, int j, int k) const { return values[index(i, j, k)]; }
};

// A trilinear sample and the smallest and largest of the 8 values it blends:
// the bounds of the MacCormack limiter (Selle et al. 2008, §3.1).
struct StencilSample {
    double value;
    double min;
    double max;
};

// Trilinear interpolation at lattice coordinate g (sample (i, j, k) at g = (i, j, k)),
// clamped to the lattice, so points outside take the value of the nearest edge.
double sampleTrilinear(const GridField& field, const glm::dvec3& g);
StencilSample sampleWithBounds(const GridField& field, const glm::dvec3& g);

}  // namespace eikon::sim
