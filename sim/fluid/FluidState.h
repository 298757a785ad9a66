// Everything the solver advances: the MAC velocity and the cell-centred
// scalars, plus the last pressure (the next solve's initial guess).
#pragma once

#include "sim/fluid/MacGrid.h"

namespace eikon::sim {

struct FluidState {
    MacGrid flow;               // face velocities, m/s
    GridField temperature;      // K
    GridField concentration;    // fraction of liquid B (a dense second gas in air), [0, 1]
    GridField dye;              // passive dye, units of SimDesc::dyeExtinction's "per unit"
    GridField pressure;         // p·Δt/ρ of the last projection, m²/s

    FluidState(const GridSpec& cells, double ambientTemperature)
        : flow(cells),
          temperature(flow.cellField(ambientTemperature)),
          concentration(flow.cellField(0.0)),
          dye(flow.cellField(0.0)),
          pressure(flow.cellField(0.0)) {}
};

}  // namespace eikon::sim
