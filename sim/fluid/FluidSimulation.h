// The built-in fluid and mixing solver, as the frame loop sees it.
//
// One substep ([Stam99] §2; [Bridson15] ch. 2–6):
//   sources   hot plates, jet scalars, Boussinesq buoyancy, vorticity
//             confinement (VorticityConfinement.h), jet velocities
//             (fixed scalars are set again after advection, jet velocities before projection)
//   advection MacCormack with the extrema limiter (Advection.h), velocity and
//             scalars; in a closed domain scalar totals are restored (MassCorrection.h)
//   diffusion backward Euler for the increment: viscosity, heat, concentration,
//             dye, by red–black Gauss–Seidel, or by CG where a step is stiff (Diffusion.h)
//   projection MG-preconditioned CG to the pressure tolerance (PressureSolver.h)
// Every field is checked for NaN/Inf after every phase (FiniteCheck.h).
// A frame advances SimDesc::frameTime in at least SimDesc::substeps equal
// substeps, more where the fastest face would cross more than SimDesc::cfl cells,
// and refuses (InputError) a frame that would need more than SimDesc::maxSubsteps.
// The substeps run here on the CPU, or on an attached FluidDevice (the GPU,
// sim/gpu/GpuFluidBackend.h), which runs the same phases.
#pragma once

#include "bridge/grid/GridSpec.h"
#include "bridge/scene/Scene.h"
#include "sim/fluid/Advection.h"
#include "sim/fluid/Boundaries.h"
#include "sim/fluid/Diffusion.h"
#include "sim/fluid/FiniteCheck.h"
#include "sim/fluid/FluidDevice.h"
#include "sim/fluid/FluidState.h"
#include "sim/fluid/FrameReport.h"
#include "sim/fluid/PhaseTiming.h"
#include "sim/fluid/PressureSolver.h"
#include "sim/fluid/Sources.h"
#include "sim/field/SolverScalars.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace eikon::sim {

class FluidSimulation {
public:
    // The solver grid is desc.resolution over desc.bounds (the render grid's
    // bounds when absent); the optical mapping (sim/optics/OpticalMapping.h)
    // reads scalars(). Throws InputError for a source region without cells.
    FluidSimulation(const SimDesc& desc, const GridSpec& renderGrid);

    // Runs the substeps of one frame. Throws InputError naming field, cell and
    // phase the moment a NaN or Inf appears, and at sim.max_substeps before
    // a substep the frame's count would exceed it.
    void advanceFrame();

    // One substep of dt seconds (tests, benchmarks); lastTimings() then holds
    // its phases, lastReport() a count of 1 and nothing else.
    void step(double dt);

    // Temperature, concentration and dye on the solver grid, for the optical mapping.
    SolverScalars scalars() const;

    // From now on the substeps run on `device`, which takes the current state.
    // Attach after the last addSolidMask.
    void attachDevice(std::unique_ptr<FluidDevice> device);
    // "cpu", or the attached device's name.
    std::string deviceName() const { return device_ ? device_->name() : "cpu"; }
    // Bytes moved between host and device since the last call (0 on the CPU).
    std::uint64_t takeBusBytes() { return device_ ? device_->takeBusBytes() : 0; }
    const SimDesc& desc() const { return desc_; }
    const SceneSources& sources() const { return sources_; }

    double time() const { return time_; }
    int lastSubsteps() const { return report_.substeps; }
    // The last frame's (or step's) substeps, fastest crossing and scalar budgets.
    const FluidFrameReport& lastReport() const { return report_; }
    const std::vector<PhaseTiming>& lastTimings() const { return timings_; }

    // Adds solid cells (one byte per solver cell, x fastest; non-zero = solid)
    // to the obstacles of the scene, e.g. from a voxelized mesh.
    void addSolidMask(const std::vector<std::uint8_t>& solid);

    const GridSpec& solverGrid() const { return state_.flow.grid; }
    const FluidDomain& domain() const { return domain_; }
    // The state on the host, brought up to date from an attached device
    // first; the mutable one is taken back to the device before the next substep.
    FluidState& state();
    const FluidState& state() const;
    // The host state with temperature, concentration and dye brought up to
    // date, but not the velocity and pressure (which may lag an attached
    // device): for reading the scalars alone without moving the rest.
    const FluidState& scalarState() const;

private:
    void substep(double dt);
    void substepOnCpu(double dt);
    double maxCellCrossingRate();
    // Advection of the scalars and the velocity in a closed domain, with each
    // scalar's total restored (MassCorrection.h).
    void advectConserving(const std::vector<GridField*>& scalars, double dt);
    void rebuildRoles();
    // Throws at the first NaN or Inf in the fields a phase wrote (a mask of
    // kScalars, kVelocity, kPressure), naming the field and the cell.
    enum CheckedFields : unsigned { kScalars = 1, kVelocity = 2, kPressure = 4 };
    void checkFinite(const SolverPhase& phase, unsigned fields) const;
    // Σ (φ − φ_ambient)·V of temperature, concentration and dye (FrameReport.h).
    std::array<double, 3> scalarTotals() const;
    // Adds changes of Σ φ (over cells) to the budgets' sources.
    void addToSources(const std::array<double, 3>& change);
    // With the totals at the frame's start: the totals now, and advection as
    // the rest of the change.
    void closeBudgets(const std::array<double, 3>& start);
    PhaseTiming& timing(int phase) { return timings_[static_cast<std::size_t>(phase)]; }

    SimDesc desc_;
    FluidState state_;
    FluidDomain domain_;
    SceneSources sources_;
    std::unique_ptr<PressureSolver> pressure_;
    AdvectionScratch advection_;
    // One implicit diffusion per field: each caches its operator for its diffusivity.
    std::array<ImplicitDiffusion, 3> velocityDiffusion_;
    ImplicitDiffusion temperatureDiffusion_, concentrationDiffusion_, dyeDiffusion_;
    std::vector<PhaseTiming> timings_;
    void updateTime();
    double time_ = 0.0;         // simulated time: frames_ · frame time + steppedTime_
    long long frames_ = 0;      // advanceFrame calls
    double steppedTime_ = 0.0;  // Σ dt of step() calls
    FluidFrameReport report_;
    std::unique_ptr<FluidDevice> device_;
    // Which copy is newer, while a device is attached; the host's scalars
    // may be current while the rest of its state is not (scalars()).
    mutable bool deviceAhead_ = false;
    mutable bool hostScalarsCurrent_ = true;
    bool hostAhead_ = false;
};

}  // namespace eikon::sim
