// What drives the flow: Boussinesq buoyancy from temperature and
// concentration, and the sources of the scene (hot plates held at a
// temperature, jets that impose a velocity and inject concentration and dye).
#pragma once

#include "bridge/scene/Scene.h"
#include "sim/fluid/Boundaries.h"
#include "sim/fluid/Diffusion.h"
#include "sim/fluid/FluidState.h"

#include <array>
#include <vector>

namespace eikon::sim {

// Boussinesq approximation ([Bridson15] §6.2; [Fedkiw01] eq. 8 with its α, β
// exchanged to name the physical coefficients): density
// ρ = ρ0 (1 − β (T − T_amb) + α c), so the buoyant acceleration is
// f = g (α c − β (T − T_amb)): hot fluid rises, dense fluid sinks. Adds Δt·f
// to every free face, from the mean of its two cells.
void addBuoyancy(FluidState& state, const FluidDomain& domain, const SimDesc& desc, double dt);

class SceneSources {
public:
    // Finds the cells and faces of every source region; throws InputError
    // ("sim.sources[i]") for a region that holds no cell centre of the solver grid.
    SceneSources(const SimDesc& desc, const MacGrid& mac, const FluidDomain& domain);

    // Hot plates: temperature; jets: concentration and dye. Returns what
    // that changed Σ T, Σ c and Σ dye by (over cells, not volume).
    std::array<double, 3> applyScalars(FluidState& state) const;
    // Whether a hot plate holds cells (the temperature diffusion then
    // conducts heat out of them).
    bool holdsTemperature() const;
    // Jets: the velocity of every free face in the region.
    void applyVelocity(FluidState& state) const;
    // Marks hot-plate cells as Fixed for temperature diffusion.
    void holdTemperature(std::vector<DiffusionRole>& roles) const;

private:
    struct Region {
        SimDesc::Source source;
        std::vector<std::size_t> cells;
        std::array<std::vector<std::size_t>, 3> faces;  // jets only
    };
    std::vector<Region> regions_;
};

}  // namespace eikon::sim
