// A stiff fluid run shared by the fluid tests and the stability suite: a
// solid-body vortex (1 m/s at the rim) over a hot lower half in a closed unit
// box, stepped at a given CFL number with every diffusivity a given multiple
// of the explicit limit Δt·D/h² = 1/6, without gravity.
#pragma once

#include <functional>

namespace eikon::sim {

struct StiffRunResult {
    double initialEnergy = 0.0;        // kinetic, J per unit density
    double maxEnergyRatio = 0.0;       // max over steps of energy / initial energy
    double minTemperature = 0.0, maxTemperature = 0.0;  // K, after the last step
    double ambientTemperature = 0.0, hotExcess = 0.0;   // K: the initial range is [ambient, ambient + excess]
    bool finite = true;                // every velocity and temperature finite after every step
};

class FluidSimulation;

// `place` may attach a device to the solver once its initial state is set
// (the GPU backend's tests); by default the run stays on the CPU.
StiffRunResult runStiffVortex(int cells, double cfl, double diffusionOverExplicitLimit, int steps,
                              const std::function<void(FluidSimulation&)>& place = {});

}  // namespace eikon::sim
