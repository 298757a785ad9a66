// The solver's own fields — velocity, temperature, concentration, dye —
// resampled onto the render grid for export (VTK, OpenVDB), next to the
// optical fields the tracer sees.
#pragma once

#include "bridge/grid/GridSpec.h"
#include "bridge/grid/NamedArrays.h"
#include "sim/fluid/FluidState.h"

#include <vector>

namespace eikon::sim {

// "velocity" (3 components, m/s, each component interpolated on its own MAC
// faces), "temperature" (K), "concentration", "dye", trilinear at the render
// cells' centres; render cells outside the solver box see the ambient fluid
// at rest (ambientTemperature, no liquid B, no dye).
std::vector<NamedArray> solverArrays(const FluidState& state, const GridSpec& renderGrid,
                                         double ambientTemperature);

}  // namespace eikon::sim
