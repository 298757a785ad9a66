// What one frame of the fluid solver did, for the frame report
// (report.jsonl "fluid", docs/scene-format.md): the substeps it took, how far
// the fastest flow moved in one of them, and what the sources put into each
// scalar, so that conservation can be checked from outside.
#pragma once

#include "bridge/scene/Scene.h"

#include <string>

namespace eikon::sim {

// Cells the fastest face may cross in one substep before the advected fields
// stop meaning much. Semi-Lagrangian advection is stable at any step, but its
// back-traced departure points then jump over the flow's structures;
// [Bridson15] ch. 3, "Time Step Size" (after Foster and Fedkiw), keeps the
// step within about five cells of the fastest velocity.
constexpr double kMeaningfulCellsPerSubstep = 5.0;

// The change of a scalar's volume integral Σ φ·V over a frame (V the cell
// volume): K·m³ for temperature (× ρ·c_p for joules), m³ of liquid B for
// concentration, m³ × dye units for dye.
struct ScalarBudget {
    // Put in by the sources: hot-plate and jet cells set to their values
    // again, and what diffuses out of held cells (the implicit diffusion has
    // Neumann edges and moves nothing into solids, Diffusion.h).
    double sources = 0.0;
    // The rest of the frame's change: what advection carried through open
    // faces, or in a closed box what the mass correction could not put back
    // (MassCorrection.h), and the linear solves' rounding. Buoyancy and
    // projection touch no scalar.
    double advection = 0.0;
    // Σ (φ − φ_ambient)·V at the end of the frame (φ_ambient: the ambient
    // temperature, 0 for concentration and dye).
    double total = 0.0;
};

struct FluidFrameReport {
    int substeps = 0;
    // max over the frame's substeps of max_faces |u_a|·Δt/h_a after each:
    // the cells the fastest face crosses in one substep at the velocity the
    // substep produced.
    double cellsPerSubstep = 0.0;
    // describeFastFlow's words for this frame: empty, or what is wrong and what to change.
    std::string fastFlow;
    // Whether the budgets were kept: by a frame on the CPU backend (the GPU
    // backend keeps its fields in GPU memory and reports none; a lone
    // FluidSimulation::step keeps none).
    bool budgetsKept = false;
    ScalarBudget heat, concentration, dye;
};

// Empty when the fastest face stayed within kMeaningfulCellsPerSubstep cells
// a substep; otherwise what was found and what to change.
std::string describeFastFlow(const FluidFrameReport& report, const SimDesc& desc);

// The refusal of a frame that would need more than sim.max_substeps
// substeps: throws InputError at sim.max_substeps with the count, the
// fastest crossing rate and what to change.
[[noreturn]] void refuseSubsteps(long long frame, double needed, double crossingRate, const SimDesc& desc);

}  // namespace eikon::sim
