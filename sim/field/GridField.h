// A dense 3D array of doubles sampled on a regular lattice: the cell-centred
// scalars and each staggered velocity component of a MAC grid
// ([Bridson15] §2.4) are GridFields that differ only in size and in where
// sample (0, 0, 0) sits.
#pragma once

#include <glm/vec3.hpp>

#include <algorithm>
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
// the bounds of the MacCormack limiter ([Selle08] §3.1).
struct StencilSample {
    double value;
    double min;
    double max;
};

namespace detail {

// The lower lattice index, the step to the next one (0 on a one-sample axis)
// and the fraction toward it, along one axis.
struct AxisCell {
    int lower;
    int step;
    double t;
};

inline AxisCell locate(double g, int n) {
    if (n == 1) return {0, 0, 0.0};
    const double clamped = std::clamp(g, 0.0, static_cast<double>(n - 1));
    const int lower = std::min(static_cast<int>(clamped), n - 2);
    return {lower, 1, clamped - lower};
}

// The eight values around g, x fastest, and the fractions along each axis.
struct Corners {
    double v[8];
    double wx, wy, wz;
};

inline Corners gather(const GridField& field, const glm::dvec3& g) {
    const AxisCell x = locate(g.x, field.size.x);
    const AxisCell y = locate(g.y, field.size.y);
    const AxisCell z = locate(g.z, field.size.z);
    const std::size_t sy = static_cast<std::size_t>(field.size.x) * static_cast<std::size_t>(y.step);
    const std::size_t sz = static_cast<std::size_t>(field.size.x) * static_cast<std::size_t>(field.size.y) *
                           static_cast<std::size_t>(z.step);
    const std::size_t sx = static_cast<std::size_t>(x.step);
    const double* p = field.values.data() + field.index(x.lower, y.lower, z.lower);
    return {{p[0], p[sx], p[sy], p[sx + sy], p[sz], p[sx + sz], p[sy + sz], p[sx + sy + sz]}, x.t, y.t, z.t};
}

inline double blend(const Corners& c) {
    const double x00 = c.v[0] + c.wx * (c.v[1] - c.v[0]);
    const double x10 = c.v[2] + c.wx * (c.v[3] - c.v[2]);
    const double x01 = c.v[4] + c.wx * (c.v[5] - c.v[4]);
    const double x11 = c.v[6] + c.wx * (c.v[7] - c.v[6]);
    const double y0 = x00 + c.wy * (x10 - x00);
    const double y1 = x01 + c.wy * (x11 - x01);
    return y0 + c.wz * (y1 - y0);
}

}  // namespace detail

// Trilinear interpolation at lattice coordinate g (sample (i, j, k) at g = (i, j, k)),
// clamped to the lattice, so points outside take the value of the nearest edge.
// Inline: advection calls these several times per sample.
inline double sampleTrilinear(const GridField& field, const glm::dvec3& g) {
    return detail::blend(detail::gather(field, g));
}

inline StencilSample sampleWithBounds(const GridField& field, const glm::dvec3& g) {
    const detail::Corners c = detail::gather(field, g);
    double low = c.v[0], high = c.v[0];
    for (int n = 1; n < 8; ++n) {
        low = std::min(low, c.v[n]);
        high = std::max(high, c.v[n]);
    }
    return {detail::blend(c), low, high};
}

}  // namespace eikon::sim
