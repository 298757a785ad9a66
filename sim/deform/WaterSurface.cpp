#include "sim/deform/WaterSurface.h"

#include "bridge/core/Error.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>

namespace eikon::sim {

WaterSurface::WaterSurface(const WaterDesc& desc)
    : desc_(desc),
      height_(static_cast<std::size_t>(desc.cells.x) * desc.cells.y, 0.0),
      previousHeight_(height_),
      velocity_(height_),
      previousVelocity_(height_),
      dropApplied_(desc.drops.size(), false) {
    addSwell();
    previousHeight_ = height_;
}

double WaterSurface::spacingX() const { return (desc_.basinMax.x - desc_.basinMin.x) / (desc_.cells.x - 1); }
double WaterSurface::spacingZ() const { return (desc_.basinMax.z - desc_.basinMin.z) / (desc_.cells.y - 1); }

glm::dvec2 WaterSurface::nodePosition(int i, int k) const {
    return {desc_.basinMin.x + i * spacingX(), desc_.basinMin.z + k * spacingZ()};
}

double WaterSurface::stableStep() const {
    const double dx = spacingX(), dz = spacingZ();
    return 0.9 / (desc_.waveSpeed * std::sqrt(1.0 / (dx * dx) + 1.0 / (dz * dz)));
}

// Five-point Laplacian; a wall node's missing neighbour mirrors the node
// itself, so the flux through the wall is zero (∂h/∂n = 0).
void WaterSurface::laplacian(const std::vector<double>& h, std::vector<double>& out) const {
    const int nx = desc_.cells.x, nz = desc_.cells.y;
    const double wx = 1.0 / (spacingX() * spacingX()), wz = 1.0 / (spacingZ() * spacingZ());
    out.assign(h.size(), 0.0);
    for (int k = 0; k < nz; ++k)
        for (int i = 0; i < nx; ++i) {
            const double centre = h[index(i, k)];
            double sum = 0.0;
            if (i > 0) sum += wx * (h[index(i - 1, k)] - centre);
            if (i + 1 < nx) sum += wx * (h[index(i + 1, k)] - centre);
            if (k > 0) sum += wz * (h[index(i, k - 1)] - centre);
            if (k + 1 < nz) sum += wz * (h[index(i, k + 1)] - centre);
            out[index(i, k)] = sum;
        }
}

void WaterSurface::addSwell() {
    if (desc_.swellAmplitude <= 0.0) return;
    std::mt19937 random(desc_.seed);
    std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi);
    const double wavenumber = 2.0 * std::numbers::pi / desc_.swellWavelength;
    for (int wave = 0; wave < desc_.swellWaves; ++wave) {
        const double direction = angle(random), phase = angle(random);
        const glm::dvec2 k = wavenumber * glm::dvec2(std::cos(direction), std::sin(direction));
        for (int kz = 0; kz < desc_.cells.y; ++kz)
            for (int i = 0; i < desc_.cells.x; ++i)
                height_[index(i, kz)] += std::cos(glm::dot(k, nodePosition(i, kz)) + phase);
    }
    double meanSquare = 0.0;
    for (double h : height_) meanSquare += h * h;
    meanSquare /= static_cast<double>(height_.size());
    const double scale = meanSquare > 0.0 ? desc_.swellAmplitude / std::sqrt(meanSquare) : 0.0;
    for (double& h : height_) h *= scale;
}

void WaterSurface::applyDrop(const WaterDrop& drop) {
    for (int k = 0; k < desc_.cells.y; ++k)
        for (int i = 0; i < desc_.cells.x; ++i) {
            const glm::dvec2 d = nodePosition(i, k) - drop.position;
            height_[index(i, k)] -= drop.amplitude * std::exp(-glm::dot(d, d) / (2.0 * drop.radius * drop.radius));
        }
}

void WaterSurface::addDisturbances(std::vector<double>& force) const {
    for (const WaterDisturbance& mover : desc_.disturbances) {
        if (time_ < mover.from || time_ >= mover.until) continue;
        const glm::dvec2 centre = mover.start + (time_ - mover.from) * mover.velocity;
        for (int k = 0; k < desc_.cells.y; ++k)
            for (int i = 0; i < desc_.cells.x; ++i) {
                const glm::dvec2 d = nodePosition(i, k) - centre;
                force[index(i, k)] -= mover.strength * std::exp(-glm::dot(d, d) / (2.0 * mover.radius * mover.radius));
            }
    }
}

void WaterSurface::step(double dt) {
    for (std::size_t d = 0; d < desc_.drops.size(); ++d)
        if (!dropApplied_[d] && desc_.drops[d].time <= time_) {
            applyDrop(desc_.drops[d]);
            dropApplied_[d] = true;
        }
    std::vector<double> acceleration;
    laplacian(height_, acceleration);
    const double c2 = desc_.waveSpeed * desc_.waveSpeed;
    for (double& a : acceleration) a *= c2;
    addDisturbances(acceleration);
    const double half = 0.5 * desc_.damping * dt;
    previousVelocity_ = velocity_;
    previousHeight_ = height_;
    for (std::size_t n = 0; n < height_.size(); ++n) {
        velocity_[n] = ((1.0 - half) * velocity_[n] + dt * acceleration[n]) / (1.0 + half);
        height_[n] += dt * velocity_[n];
    }
    time_ += dt;
}

void WaterSurface::advanceTo(double time) {
    const double remaining = time - time_;
    if (remaining <= 0.0) return;
    const int steps = static_cast<int>(std::ceil(remaining / stableStep()));
    for (int s = 0; s < steps; ++s) step(remaining / steps);
}

double WaterSurface::energy() const {
    std::vector<double> stiffness;  // L h^{n+1}
    laplacian(height_, stiffness);
    double kinetic = 0.0, potential = 0.0;
    for (std::size_t n = 0; n < height_.size(); ++n) {
        kinetic += velocity_[n] * velocity_[n];
        potential -= previousHeight_[n] * stiffness[n];
    }
    const double area = spacingX() * spacingZ();
    return 0.5 * area * (kinetic + desc_.waveSpeed * desc_.waveSpeed * potential);
}

// Top: the height field; bottom: a fan to the centre of the basin's floor;
// walls: quads between the top's boundary ring and the floor's.
TriangleMesh WaterSurface::mesh() const {
    const int nx = desc_.cells.x, nz = desc_.cells.y;
    TriangleMesh mesh;
    mesh.vertices.reserve(height_.size() + 2 * (nx + nz));
    for (int k = 0; k < nz; ++k)
        for (int i = 0; i < nx; ++i) {
            const glm::dvec2 p = nodePosition(i, k);
            mesh.vertices.emplace_back(p.x, desc_.basinMax.y + height_[index(i, k)], p.y);
        }
    auto top = [&](int i, int k) { return static_cast<int>(index(i, k)); };
    for (int k = 0; k + 1 < nz; ++k)
        for (int i = 0; i + 1 < nx; ++i) {
            mesh.triangles.emplace_back(top(i, k), top(i, k + 1), top(i + 1, k + 1));
            mesh.triangles.emplace_back(top(i, k), top(i + 1, k + 1), top(i + 1, k));
        }
    std::vector<std::pair<int, int>> ring;  // boundary nodes, walked +x, +z, −x, −z
    for (int i = 0; i < nx - 1; ++i) ring.emplace_back(i, 0);
    for (int k = 0; k < nz - 1; ++k) ring.emplace_back(nx - 1, k);
    for (int i = nx - 1; i > 0; --i) ring.emplace_back(i, nz - 1);
    for (int k = nz - 1; k > 0; --k) ring.emplace_back(0, k);
    const int firstBottom = static_cast<int>(mesh.vertices.size());
    for (const auto& [i, k] : ring) {
        const glm::dvec2 p = nodePosition(i, k);
        mesh.vertices.emplace_back(p.x, desc_.basinMin.y, p.y);
    }
    const int centre = static_cast<int>(mesh.vertices.size());
    mesh.vertices.emplace_back(0.5 * (desc_.basinMin.x + desc_.basinMax.x), desc_.basinMin.y,
                               0.5 * (desc_.basinMin.z + desc_.basinMax.z));
    const int count = static_cast<int>(ring.size());
    for (int r = 0; r < count; ++r) {
        const int next = (r + 1) % count;
        const int ta = top(ring[r].first, ring[r].second), tb = top(ring[next].first, ring[next].second);
        const int ba = firstBottom + r, bb = firstBottom + next;
        mesh.triangles.emplace_back(ta, tb, bb);
        mesh.triangles.emplace_back(ta, bb, ba);
        mesh.triangles.emplace_back(centre, ba, bb);
    }
    EIKON_CHECK_MSG(static_cast<int>(mesh.triangles.size()) == desc_.triangleCount(),
                    "the water body's triangles are as many as WaterDesc::triangleCount says");
    return mesh;
}

}  // namespace eikon::sim
