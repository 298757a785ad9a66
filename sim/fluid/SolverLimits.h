// Stopping rules shared by the solver's backends (FluidSimulation.cpp,
// sim/gpu/GpuFluidBackend.cpp), so both solve each phase to the same point.
#pragma once

namespace eikon::sim {

constexpr double kDiffusionTolerance = 1e-8;  // relative max-norm residual of each implicit diffusion solve
constexpr int kMaxSolverIterations = 1000;    // per linear solve, diffusion or pressure

}  // namespace eikon::sim
