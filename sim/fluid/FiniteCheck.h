// The solver's guard against NaN and Inf: every field is scanned after every
// phase, and the first non-finite sample stops the run with the keys behind
// the phase that produced it, its field and its lattice index (docs/architecture.md,
// Errors and outputs: never traced silently).
#pragma once

#include "sim/field/GridField.h"

#include <string>

namespace eikon::sim {

// A point of a substep where the fields are checked, and the keys that drive
// the phase before it: what a user changes when a value there is not finite.
struct SolverPhase {
    const char* when;  // "after advection"
    const char* keys;  // "sim.cfl, sim.substeps"
};
inline constexpr SolverPhase kSubstepStart{"at the start of a substep", "sim"};  // values handed in from outside
inline constexpr SolverPhase kAfterSources{
    "after sources",
    "sim.sources, sim.thermal_expansion, sim.concentration_expansion, sim.gravity, sim.vorticity_confinement"};
inline constexpr SolverPhase kAfterAdvection{"after advection", "sim.cfl, sim.substeps"};
inline constexpr SolverPhase kAfterDiffusion{
    "after diffusion", "sim.viscosity, sim.thermal_diffusivity, sim.concentration_diffusivity, sim.dye_diffusivity"};
inline constexpr SolverPhase kAfterProjection{"after projection", "sim.pressure_tolerance"};

// Throws NumericalBreakdown (exit code 1: the input was valid, the
// solver's numbers broke down on it) "<the phase's keys> (the solver's <name> at <sample>
// (i, j, k) of sim.resolution, <when>): expected a finite value, found nan"
// for the first non-finite value. SceneFields adds the scene file.
// `sample` is "cell" for cell-centred fields and "face" for velocities.
void requireFinite(const GridField& field, const std::string& name, const std::string& sample, const SolverPhase& phase);

// The same error for sample `index` of a lattice of `size` holding `value`
// (a backend that found it elsewhere: sim/gpu/GpuFiniteCheck.h).
[[noreturn]] void throwNotFinite(const std::string& name, const std::string& sample, glm::ivec3 size,
                                 std::size_t index, double value, const SolverPhase& phase);

}  // namespace eikon::sim
