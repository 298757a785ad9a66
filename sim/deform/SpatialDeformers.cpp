#include "sim/deform/SpatialDeformers.h"

#include "sim/deform/Keyframes.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace eikon::sim {

RigidDeformer::RigidDeformer(const DeformerDesc& desc, const TriangleMesh& rest)
    : keys_(desc.keys), rest_(rest.vertices) {
    glm::dvec3 lo, hi;
    vertexBounds(rest, lo, hi);
    centre_ = 0.5 * (lo + hi);
}

void RigidDeformer::deform(double time, std::vector<glm::dvec3>& deformed) {
    const glm::dmat4 m = placementMatrix(poseAt(keys_, time));
    deformed.resize(rest_.size());
    for (std::size_t v = 0; v < rest_.size(); ++v) deformed[v] = centre_ + glm::dvec3(m * glm::dvec4(rest_[v] - centre_, 1.0));
}

TwistDeformer::TwistDeformer(const DeformerDesc& desc, const TriangleMesh& rest) : desc_(desc), rest_(rest.vertices) {}

// Rodrigues' rotation of the offset from the axis by θ = τ·s.
void TwistDeformer::deform(double time, std::vector<glm::dvec3>& deformed) {
    const double rate = glm::radians(amountAt(desc_.amount, time));
    const glm::dvec3 a = desc_.axis;
    deformed.resize(rest_.size());
    for (std::size_t v = 0; v < rest_.size(); ++v) {
        const glm::dvec3 d = rest_[v] - desc_.origin;
        const double s = glm::dot(d, a);
        const double theta = rate * s;
        const double c = std::cos(theta), sn = std::sin(theta);
        deformed[v] = desc_.origin + d * c + glm::cross(a, d) * sn + a * glm::dot(a, d) * (1.0 - c);
    }
}

BendDeformer::BendDeformer(const DeformerDesc& desc, const TriangleMesh& rest) : desc_(desc), rest_(rest.vertices) {}

// With s along the axis a and u along `toward` d, the axis becomes an arc of
// radius R = 1/κ: p' = o + w + (R − (R − u)·cos κs)·d + (R − u)·sin κs·a,
// which tends to the identity as κ → 0.
void BendDeformer::deform(double time, std::vector<glm::dvec3>& deformed) {
    const double curvature = glm::radians(amountAt(desc_.amount, time));
    const glm::dvec3 a = desc_.axis, d = desc_.toward;
    deformed.resize(rest_.size());
    for (std::size_t v = 0; v < rest_.size(); ++v) {
        const glm::dvec3 offset = rest_[v] - desc_.origin;
        const double s = glm::dot(offset, a), u = glm::dot(offset, d);
        const glm::dvec3 w = offset - s * a - u * d;
        if (std::abs(curvature) < 1e-12) {
            deformed[v] = rest_[v];
            continue;
        }
        const double radius = 1.0 / curvature;
        const double angle = curvature * s;
        deformed[v] = desc_.origin + w + (radius - (radius - u) * std::cos(angle)) * d + (radius - u) * std::sin(angle) * a;
    }
}

}  // namespace eikon::sim
