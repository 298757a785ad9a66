// A backend that runs the solver's substeps away from the host's FluidState:
// the GPU (sim/gpu/GpuFluidBackend.h). FluidSimulation keeps the frame logic
// (substep count, time, phase records) and the host copy of the state, and
// moves the state across only when one side needs what the other changed:
// its state() before a substep uploads, a substep before state() downloads.
#pragma once

#include "sim/fluid/FluidState.h"
#include "sim/fluid/PhaseTiming.h"

#include <cstdint>
#include <string>
#include <vector>

namespace eikon::sim {

class FluidDevice {
public:
    virtual ~FluidDevice() = default;

    virtual std::string name() const = 0;  // "gpu"
    // Takes `state` as the current state.
    virtual void upload(const FluidState& state) = 0;
    // Writes the current state into `state`.
    virtual void download(FluidState& state) = 0;
    // Only temperature, concentration and dye (what the optical mapping reads).
    virtual void downloadScalars(FluidState& state) = 0;
    // max over faces and axes of |u_a| / h_a (MacGrid::maxCellCrossingRate).
    virtual double maxCellCrossingRate() = 0;
    // One substep of dt seconds, the phases of FluidSimulation.h in their
    // order; adds each phase's time, iterations and residual to timings
    // (sources, advection, diffusion, projection). Throws InputError naming
    // field, sample and phase where a value is not finite.
    virtual void substep(double dt, std::vector<PhaseTiming>& timings) = 0;
    // Bytes moved between host and device memory since the last call:
    // uploads, downloads, and the numbers a stopping test, the CFL count or
    // a NaN check reads back.
    virtual std::uint64_t takeBusBytes() = 0;
};

}  // namespace eikon::sim
