// Vorticity confinement ([Fedkiw01] §3, eqs. 9–12): the solver's coarse
// cells and its numerical dissipation damp the small eddies of real air,
// and this force puts their spin back where the flow already turns:
//   ω = ∇ × u                    (eq. 9)
//   N = η / |η|,  η = ∇|ω|       (eq. 10)
//   f = ε · h · (N × ω)          (eq. 11)
// with ε >= 0 (sim.vorticity_confinement) and h the cell's edge (the
// geometric mean of the three edges where they differ), so that f → 0 as
// the grid is refined and the flow converges to that without confinement.
//
// Discretization, the same on the CPU and the GPU
// (shaders/sim/vorticity.comp, vorticity_confinement.comp): ū at each cell
// centre is the mean of its two faces per axis; ω and ∇|ω| are central
// differences over the neighbouring cells, one-sided at the box's edges
// (a zero difference along an axis one cell thick); N is zero where
// |η| < kMinVorticityGradient. Each free face gets Δt times the mean of f
// over its two cells (an open face: its one inside cell), as buoyancy does
// (Sources.h); fixed faces are left alone.
#pragma once

#include "sim/fluid/Boundaries.h"
#include "sim/fluid/FluidState.h"

namespace eikon::sim {

// |∇|ω|| below this (1/(m·s)) gives no direction N: a flow so uniform in
// its spin has no eddy to confine.
constexpr double kMinVorticityGradient = 1e-6;

// The cell edge h of eq. 11: the geometric mean of the three edges.
double confinementLength(const glm::dvec3& h);

// Adds Δt·f (eq. 11, ε = epsilon) to every free face of state.flow.
void addVorticityConfinement(FluidState& state, const FluidDomain& domain, double epsilon, double dt);

}  // namespace eikon::sim
