// A water body whose surface height h(x, z, t) obeys the damped 2D wave
// equation h_tt = c²∇²h − γ·h_t + f, with reflecting walls (∂h/∂n = 0), drops
// and moving disturbances as inputs, closed into a triangle mesh each frame
// (pool caustics, [Hu07] Fig. 28).
//
// Discretisation: heights on a node grid spanning the basin, the five-point
// Laplacian with mirrored walls (−L is symmetric positive semidefinite), and
// leapfrog in time with the damping centred:
//   v^{n+½} = ((1 − γΔt/2)·v^{n−½} + Δt·(c²L h^n + f^n)) / (1 + γΔt/2),
//   h^{n+1} = h^n + Δt·v^{n+½},
// stable for c·Δt·√(1/Δx² + 1/Δz²) ≤ 1. The discrete energy
//   E^{n+½} = ½·ΣA·(v^{n+½})² + ½·c²·ΣA·h^n·(−L h^{n+1})
// is then exactly conserved without damping and input, and decreases by
// (γΔt/4)·ΣA·(v^{n+½} + v^{n−½})² per step with damping.
#pragma once

#include "bridge/mesh/TriangleMesh.h"
#include "bridge/scene/MeshObjectDesc.h"

#include <vector>

namespace eikon::sim {

class WaterSurface {
public:
    explicit WaterSurface(const WaterDesc& desc);

    // Steps (at the stable Δt or less) until `time`, s; applies drops whose
    // time has come and disturbances active on the way.
    void advanceTo(double time);
    void step(double dt);

    double time() const { return time_; }
    double stableStep() const;  // 0.9 × the largest stable Δt
    int nodesX() const { return desc_.cells.x; }
    int nodesZ() const { return desc_.cells.y; }
    double spacingX() const;
    double spacingZ() const;
    glm::dvec2 nodePosition(int i, int k) const;  // (x, z)
    // Height above the rest level at node (i, k), m.
    double height(int i, int k) const { return height_[index(i, k)]; }
    // Every node's height, x fastest, and the basin they span.
    const std::vector<double>& heights() const { return height_; }
    const WaterDesc& desc() const { return desc_; }
    void setHeight(int i, int k, double value) { height_[index(i, k)] = value; }
    // E^{n+½} of the last step, in m⁴/s² (per unit density).
    double energy() const;

    // The water body: the surface on top, the basin's walls and bottom.
    TriangleMesh mesh() const;

private:
    std::size_t index(int i, int k) const { return static_cast<std::size_t>(k) * desc_.cells.x + i; }
    void laplacian(const std::vector<double>& h, std::vector<double>& out) const;
    void addSwell();
    void applyDrop(const WaterDrop& drop);
    void addDisturbances(std::vector<double>& force) const;

    WaterDesc desc_;
    double time_ = 0.0;
    std::vector<double> height_;          // h^n
    std::vector<double> previousHeight_;  // h^{n−1}
    std::vector<double> velocity_;        // v^{n−½}
    std::vector<double> previousVelocity_;
    std::vector<bool> dropApplied_;
};

}  // namespace eikon::sim
