// Power landing on a circle about the centre of a square texel map, shared
// among the texels the circle crosses by the length of circle inside each:
// the noise-free deposit of a ring of rays for references whose irradiance
// depends only on the distance from an axis (SphereCaustic, and the accuracy
// suite's radial maps). For tests only.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

namespace eikon::reference {

// Spreads power landing on the circle of radius rho about the receiver's
// centre over the texels the circle crosses, each by the fraction of the
// circle's length inside it: the circle's arcs of the first octant
// (0 ≤ φ ≤ π/4) between the grid lines it crosses, mirrored into the eight
// octants (the texel grid is symmetric about the centre for an even
// resolution).
class CircleDeposit {
public:
    // A square map of resolution² texels (resolution even) and edge `size`,
    // power[j·resolution + i] with the centre at the map's middle.
    CircleDeposit(int resolution, double size, std::vector<double>& power)
        : half_(resolution / 2), texel_(size / resolution), power_(power) {}

    void add(double rho, double weight) {
        if (rho >= std::sqrt(2.0) * half_ * texel_) return;  // past the corners: no texel (and O(rho) lines to walk)
        if (rho <= 0.0) {
            for (int image = 0; image < 4; ++image) addTexel(0, 0, image, 0.25 * weight);
            return;
        }
        // Crossings of the lines z = k·texel (φ rising from 0) and x = k·texel
        // (φ rising toward π/4 as k falls), merged in order of φ.
        const double diagonal = rho / std::sqrt(2.0);
        int zLine = 1, xLine = static_cast<int>(std::floor(rho / texel_));
        if (xLine * texel_ >= rho) --xLine;
        const double lastZ = std::floor(diagonal / texel_);
        double phi = 0.0;
        for (;;) {
            const double nextZ = zLine <= lastZ ? std::asin(std::min(1.0, zLine * texel_ / rho)) : kOctant;
            const double nextX = xLine * texel_ > diagonal ? std::acos(std::min(1.0, xLine * texel_ / rho)) : kOctant;
            const double next = std::min({nextZ, nextX, kOctant});
            if (next > phi) {
                const double middle = 0.5 * (phi + next);
                const int i = static_cast<int>(rho * std::cos(middle) / texel_);
                const int j = static_cast<int>(rho * std::sin(middle) / texel_);
                const double share = weight * (next - phi) / (2.0 * std::numbers::pi);
                for (int image = 0; image < 4; ++image) {
                    addTexel(i, j, image, share);
                    addTexel(j, i, image, share);
                }
            }
            if (next >= kOctant) return;
            phi = next;
            if (nextZ <= nextX) ++zLine;
            else --xLine;
        }
    }

private:
    static constexpr double kOctant = std::numbers::pi / 4.0;

    // Texel (i, j) of the quadrant x, z ≥ 0, mirrored into quadrant `image`.
    void addTexel(int i, int j, int image, double weight) {
        if (i >= half_ || j >= half_) return;
        const int x = (image & 1) ? half_ - 1 - i : half_ + i;
        const int z = (image & 2) ? half_ - 1 - j : half_ + j;
        power_[static_cast<std::size_t>(z) * (2 * half_) + x] += weight;
    }

    int half_;
    double texel_;
    std::vector<double>& power_;
};

}  // namespace eikon::reference
