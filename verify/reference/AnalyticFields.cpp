#include "verify/reference/AnalyticFields.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <numbers>

namespace eikon::reference {

double MirageField::index(const glm::dvec3& x) const { return nInfinity_ - delta_ * std::exp(-x.y / scale_); }

glm::dvec3 MirageField::gradient(const glm::dvec3& x) const {
    return {0.0, delta_ / scale_ * std::exp(-x.y / scale_), 0.0};
}

double MirageField::turningHeight(double invariant) const {
    const double ratio = (nInfinity_ - invariant) / delta_;
    if (ratio <= 0.0) return std::numeric_limits<double>::infinity();  // never turns: C ≥ n∞
    return -scale_ * std::log(ratio);
}

double LuneburgField::index(const glm::dvec3& x) const {
    const double q = glm::dot(x - centre_, x - centre_) / (radius_ * radius_);
    return q < 1.0 ? std::sqrt(2.0 - q) : 1.0;
}

glm::dvec3 LuneburgField::gradient(const glm::dvec3& x) const {
    const glm::dvec3 r = x - centre_;
    const double q = glm::dot(r, r) / (radius_ * radius_);
    if (q >= 1.0) return glm::dvec3(0.0);
    return -r / (radius_ * radius_ * std::sqrt(2.0 - q));
}

double FishEyeField::index(const glm::dvec3& x) const {
    return n0_ / (1.0 + glm::dot(x, x) / (radius_ * radius_));
}

glm::dvec3 FishEyeField::gradient(const glm::dvec3& x) const {
    const double d = 1.0 + glm::dot(x, x) / (radius_ * radius_);
    return -2.0 * n0_ / (radius_ * radius_ * d * d) * x;
}

glm::dvec3 FishEyeField::image(const glm::dvec3& point) const {
    return -(radius_ * radius_ / glm::dot(point, point)) * point;
}

double GlassSphereField::index(const glm::dvec3& x) const {
    const double r = glm::length(x - centre_);
    if (width_ <= 0.0) return r < radius_ ? glass_ : 1.0;
    return 1.0 + (glass_ - 1.0) * 0.5 * std::erfc((r - radius_) / (std::numbers::sqrt2 * width_));
}

glm::dvec3 GlassSphereField::gradient(const glm::dvec3& x) const {
    const glm::dvec3 offset = x - centre_;
    const double r = glm::length(offset);
    if (width_ <= 0.0 || r == 0.0) return glm::dvec3(0.0);
    const double u = (r - radius_) / width_;
    // d/dr ½·erfc(u/√2) = −exp(−u²/2) / (√(2π)·w)
    const double dndr = -(glass_ - 1.0) * std::exp(-0.5 * u * u) / (std::sqrt(2.0 * std::numbers::pi) * width_);
    return dndr / r * offset;
}

double HeatPlumeField::index(const glm::dvec3& x) const {
    const double dx = x.x - axis_.x, dz = x.z - axis_.z;
    return reference_ - amplitude_ * std::exp(-(dx * dx + dz * dz) / (2.0 * width_ * width_)) *
                            std::exp(-(x.y - base_) / fade_);
}

glm::dvec3 HeatPlumeField::gradient(const glm::dvec3& x) const {
    const double dx = x.x - axis_.x, dz = x.z - axis_.z;
    const double deficit = amplitude_ * std::exp(-(dx * dx + dz * dz) / (2.0 * width_ * width_)) *
                           std::exp(-(x.y - base_) / fade_);
    const double s2 = width_ * width_;
    return {deficit * dx / s2, deficit / fade_, deficit * dz / s2};
}

}  // namespace eikon::reference
