#include "sim/voxelize/RowParity.h"

#include "bridge/core/Error.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace eikon::sim {

namespace {

// The integers in [lo, hi] clipped to [first, last]; empty when lo > hi
// (or either is not finite).
bool integerRange(double lo, double hi, int first, int last, int& from, int& to) {
    if (!(lo <= hi)) return false;
    const double a = std::max(std::ceil(lo), static_cast<double>(first));
    const double b = std::min(std::floor(hi), static_cast<double>(last));
    if (!(a <= b)) return false;
    from = static_cast<int>(a);
    to = static_cast<int>(b);
    return true;
}

}  // namespace

RowParity::RowParity(const std::vector<glm::dvec3>& vertices, const std::vector<glm::ivec3>& triangles,
                     glm::ivec2 rowMin, glm::ivec2 rowMax)
    : vertices_(vertices), triangles_(triangles), rowMin_(rowMin), rowMax_(glm::max(rowMax, rowMin - 1)) {
    const std::size_t rows = static_cast<std::size_t>(rowMax_.x - rowMin_.x + 1) * (rowMax_.y - rowMin_.y + 1);
    binStart_.assign(rows + 1, 0);
    // Two passes over the triangles' y–z bounds (count, then fill) build the
    // bins in compressed-row form.
    auto forEachRow = [&](const glm::ivec3& t, auto&& visit) {
        const glm::dvec3 &a = vertices_[t.x], &b = vertices_[t.y], &c = vertices_[t.z];
        int j0, j1, k0, k1;
        if (!integerRange(std::min({a.y, b.y, c.y}), std::max({a.y, b.y, c.y}), rowMin_.x, rowMax_.x, j0, j1) ||
            !integerRange(std::min({a.z, b.z, c.z}), std::max({a.z, b.z, c.z}), rowMin_.y, rowMax_.y, k0, k1))
            return;
        for (int k = k0; k <= k1; ++k)
            for (int j = j0; j <= j1; ++j) visit(rowIndex(j, k));
    };
    for (const glm::ivec3& t : triangles_) {
        EIKON_CHECK(t.x >= 0 && t.y >= 0 && t.z >= 0);
        EIKON_CHECK(static_cast<std::size_t>(std::max({t.x, t.y, t.z})) < vertices_.size());
        forEachRow(t, [&](std::size_t row) { ++binStart_[row + 1]; });
    }
    for (std::size_t r = 0; r < rows; ++r) binStart_[r + 1] += binStart_[r];
    binTriangles_.resize(binStart_[rows]);
    std::vector<std::size_t> fill(binStart_.begin(), binStart_.end() - 1);
    for (std::size_t t = 0; t < triangles_.size(); ++t)
        forEachRow(triangles_[t], [&](std::size_t row) { binTriangles_[fill[row]++] = static_cast<int>(t); });
}

std::size_t RowParity::rowIndex(int j, int k) const {
    return static_cast<std::size_t>(j - rowMin_.x) +
           static_cast<std::size_t>(rowMax_.x - rowMin_.x + 1) * static_cast<std::size_t>(k - rowMin_.y);
}

int RowParity::edgeSign(int p, int q, double j, double k, double& value) const {
    // Evaluated from the lower-indexed vertex, so that both triangles of an
    // edge get bit-identical values of opposite sign.
    const bool flip = q < p;
    const glm::dvec3& u = vertices_[flip ? q : p];
    const glm::dvec3& w = vertices_[flip ? p : q];
    const double dy = w.y - u.y, dz = w.z - u.z;
    double e = dy * (k - u.z) - dz * (j - u.y);
    int sign = (e > 0.0) - (e < 0.0);
    // On the edge's line: the sign at (j + ε, k + ε²), from ∂e/∂j = −dz and
    // then ∂e/∂k = dy.
    if (sign == 0) sign = dz != 0.0 ? (dz < 0.0 ? 1 : -1) : (dy > 0.0) - (dy < 0.0);
    if (flip) {
        e = -e;
        sign = -sign;
    }
    value = e;
    return sign;
}

void RowParity::crossings(int j, int k, std::vector<double>& xs) const {
    xs.clear();
    if (j < rowMin_.x || j > rowMax_.x || k < rowMin_.y || k > rowMax_.y) return;
    const std::size_t row = rowIndex(j, k);
    const double y = j, z = k;
    for (std::size_t n = binStart_[row]; n < binStart_[row + 1]; ++n) {
        const glm::ivec3& t = triangles_[binTriangles_[n]];
        double eab, ebc, eca;
        const int sab = edgeSign(t.x, t.y, y, z, eab);
        if (sab == 0) continue;
        if (edgeSign(t.y, t.z, y, z, ebc) != sab || edgeSign(t.z, t.x, y, z, eca) != sab) continue;
        // Barycentric weights of a, b, c are the edge functions opposite them.
        const double sum = eab + ebc + eca;
        const glm::dvec3 &a = vertices_[t.x], &b = vertices_[t.y], &c = vertices_[t.z];
        xs.push_back(sum != 0.0 ? (ebc * a.x + eca * b.x + eab * c.x) / sum : a.x);
    }
    std::sort(xs.begin(), xs.end());
}

bool RowParity::inside(const std::vector<double>& sortedCrossings, double x) {
    const auto below = std::lower_bound(sortedCrossings.begin(), sortedCrossings.end(), x) - sortedCrossings.begin();
    return below % 2 == 1;
}

}  // namespace eikon::sim
