#include "sim/fluid/GridField.h"

#include <algorithm>

namespace eikon::sim {

namespace {

// The lower lattice index and the fraction toward the next one along one axis.
struct AxisCell {
    int lower;
    int upper;
    double t;
};

AxisCell locate(double g, int n) {
    if (n == 1) return {0, 0, 0.0};
    const double clamped = std::clamp(g, 0.0, static_cast<double>(n - 1));
    const int lower = std::min(static_cast<int>(clamped), n - 2);
    return {lower, lower + 1, clamped - lower};
}

struct Corners {
    double v[8];
    double wx, wy, wz;
};

Corners gather(const GridField& field, const glm::dvec3& g) {
    const AxisCell x = locate(g.x, field.size.x);
    const AxisCell y = locate(g.y, field.size.y);
    const AxisCell z = locate(g.z, field.size.z);
    Corners c{};
    c.v[0] = field(x.lower, y.lower, z.lower);
    c.v[1] = field(x.upper, y.lower, z.lower);
    c.v[2] = field(x.lower, y.upper, z.lower);
    c.v[3] = field(x.upper, y.upper, z.lower);
    c.v[4] = field(x.lower, y.lower, z.upper);
    c.v[5] = field(x.upper, y.lower, z.upper);
    c.v[6] = field(x.lower, y.upper, z.upper);
    c.v[7] = field(x.upper, y.upper, z.upper);
    c.wx = x.t;
    c.wy = y.t;
    c.wz = z.t;
    return c;
}

double blend(const Corners& c) {
    const double x00 = c.v[0] + c.wx * (c.v[1] - c.v[0]);
    const double x10 = c.v[2] + c.wx * (c.v[3] - c.v[2]);
    const double x01 = c.v[4] + c.wx * (c.v[5] - c.v[4]);
    const double x11 = c.v[6] + c.wx * (c.v[7] - c.v[6]);
    const double y0 = x00 + c.wy * (x10 - x00);
    const double y1 = x01 + c.wy * (x11 - x01);
    return y0 + c.wz * (y1 - y0);
}

}  // namespace

GridField::GridField(glm::ivec3 sampleCount, glm::dvec3 sampleOffset, double value)
    : size(sampleCount),
      offset(sampleOffset),
      values(static_cast<std::size_t>(sampleCount.x) * static_cast<std::size_t>(sampleCount.y) *
                 static_cast<std::size_t>(sampleCount.z),
             value) {}

double sampleTrilinear(const GridField& field, const glm::dvec3& g) { return blend(gather(field, g)); }

StencilSample sampleWithBounds(const GridField& field, const glm::dvec3& g) {
    const Corners c = gather(field, g);
    const auto [low, high] = std::minmax_element(std::begin(c.v), std::end(c.v));
    return {blend(c), *low, *high};
}

}  // namespace eikon::sim
