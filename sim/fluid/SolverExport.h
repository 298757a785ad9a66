// The solver's own fields — velocity, temperature, concentration, dye —
// resampled onto the render grid for export (VTK, OpenVDB), next to the
// optical fields the tracer sees.
#pragma once

#include "bridge/grid/GridSpec.h"
#include "bridge/grid/NamedArrays.h"
#include "bridge/scene/Scene.h"
#include "sim/fluid/FluidState.h"

#include <string>
#include <vector>

namespace eikon::sim {

// "velocity" (3 components, m/s, each component interpolated on its own MAC
// faces), "temperature" (K), "concentration", "dye", trilinear at the render
// cells' centres; render cells outside the solver box see the ambient fluid
// at rest (the ambient temperature, no liquid B, no dye). An array no source
// of `desc` can change is marked constant (solverArraysNeverChange). Only
// the arrays `names` lists are made (empty: all four); `state`'s velocity is
// read only when "velocity" is among them.
std::vector<NamedArray> solverArrays(const FluidState& state, const GridSpec& renderGrid, const SimDesc& desc,
                                     const std::vector<std::string>& names = {});

// Which solver fields stay as they start — the ambient fluid at rest, no
// liquid B, no dye — for the whole run: temperature without a hot plate
// away from the ambient temperature, concentration and dye without a jet
// that carries them, velocity without any source (buoyancy and jets are
// what move the fluid).
struct ConstantSolverFields {
    bool velocity = false, temperature = false, concentration = false, dye = false;
};
ConstantSolverFields solverArraysNeverChange(const SimDesc& desc);

}  // namespace eikon::sim
