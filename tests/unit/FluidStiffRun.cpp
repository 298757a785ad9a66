#include "tests/unit/FluidStiffRun.h"

#include "sim/fluid/FluidSimulation.h"

#include <algorithm>
#include <cmath>

namespace eikon::sim {

namespace {

double kineticEnergy(const MacGrid& mac) {
    double e = 0.0;
    for (const GridField& u : mac.velocity)
        for (double v : u.values) e += 0.5 * v * v;
    return e * mac.grid.voxelVolume();
}

bool allFinite(const FluidState& s) {
    for (const GridField& u : s.flow.velocity)
        for (double v : u.values)
            if (!std::isfinite(v)) return false;
    for (double t : s.temperature.values)
        if (!std::isfinite(t)) return false;
    return true;
}

}  // namespace

StiffRunResult runStiffVortex(int cells, double cfl, double diffusionOverExplicitLimit, int steps,
                              const std::function<void(FluidSimulation&)>& place) {
    const double h = 1.0 / cells;
    const double rimSpeed = 1.0;
    const double dt = cfl * h / rimSpeed;
    const double explicitLimit = h * h / (6.0 * dt);  // largest D for forward Euler
    SimDesc desc;
    desc.resolution = glm::ivec3(cells);
    desc.gravity = glm::dvec3(0.0);
    desc.viscosity = desc.thermalDiffusivity = desc.concentrationDiffusivity = desc.dyeDiffusivity =
        diffusionOverExplicitLimit * explicitLimit;
    FluidSimulation sim(desc, GridSpec{glm::ivec3(cells), glm::dvec3(0.0), glm::dvec3(1.0)});
    FluidState& s = sim.state();
    for (int axis = 0; axis < 2; ++axis) {  // solid-body rotation about the z axis
        GridField& u = s.flow.velocity[axis];
        for (int k = 0; k < u.size.z; ++k)
            for (int j = 0; j < u.size.y; ++j)
                for (int i = 0; i < u.size.x; ++i) {
                    const glm::dvec3 p = s.flow.position(u, i, j, k) - 0.5;
                    u(i, j, k) = 2.0 * rimSpeed * (axis == 0 ? -p.y : p.x);
                }
    }
    StiffRunResult result;
    result.ambientTemperature = desc.ambientTemperature;
    result.hotExcess = 50.0;
    for (int k = 0; k < cells; ++k)
        for (int j = 0; j < cells / 2; ++j)
            for (int i = 0; i < cells; ++i) s.temperature(i, j, k) += result.hotExcess;
    result.initialEnergy = kineticEnergy(s.flow);
    if (place) place(sim);
    const FluidSimulation& stepped = sim;  // reads the state without taking it back from a device
    for (int step = 0; step < steps; ++step) {
        sim.step(dt);
        result.finite = result.finite && allFinite(stepped.state());
        result.maxEnergyRatio =
            std::max(result.maxEnergyRatio, kineticEnergy(stepped.state().flow) / result.initialEnergy);
    }
    const FluidState& last = stepped.state();
    const auto [low, high] = std::minmax_element(last.temperature.values.begin(), last.temperature.values.end());
    result.minTemperature = *low;
    result.maxTemperature = *high;
    return result;
}

}  // namespace eikon::sim
