// What the fluid solver hands to the optical mapping (sim/optics): its
// scalars on its own grid. Kept below both, so that neither includes the other.
#pragma once

#include "bridge/grid/GridSpec.h"
#include "sim/field/GridField.h"

namespace eikon::sim {

// The solver's scalars on its grid (cell-centred GridFields over `solverGrid`).
struct SolverScalars {
    const GridSpec& solverGrid;
    const GridField& temperature;
    const GridField& concentration;
    const GridField& dye;
    double ambientTemperature;
};

}  // namespace eikon::sim
