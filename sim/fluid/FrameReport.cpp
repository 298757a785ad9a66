#include "sim/fluid/FrameReport.h"

#include "bridge/core/Error.h"
#include "bridge/core/NumberFormat.h"

namespace eikon::sim {

std::string describeFastFlow(const FluidFrameReport& report, const SimDesc& desc) {
    if (!(report.cellsPerSubstep > kMeaningfulCellsPerSubstep)) return {};
    return "the fastest flow crossed " + formatRounded(report.cellsPerSubstep) + " cells in one of " +
           std::to_string(report.substeps) + " substeps of a " + formatRounded(desc.frameTime) +
           " s frame, more than the " + formatNumber(kMeaningfulCellsPerSubstep) +
           " within which advection follows the flow, so its velocities and the fields it carries mean little: "
           "lower sim.cfl (" + formatNumber(desc.cfl) + ") or raise sim.substeps (" + std::to_string(desc.substeps) +
           "), or check what drives the flow (gravity × thermal_expansion × the sources' temperature excess, "
           "jet velocities)";
}

void refuseSubsteps(long long frame, double needed, double crossingRate, const SimDesc& desc) {
    throw InputError("sim.max_substeps",
                     "at most " + std::to_string(desc.maxSubsteps) + " substeps in a frame",
                     "frame " + std::to_string(frame) + " needs " + formatRounded(needed) +
                         ": its fastest face crosses " + formatRounded(crossingRate) + " cells/s, and sim.cfl = " +
                         formatNumber(desc.cfl) + " cells a substep over sim.frame_time = " +
                         formatRounded(desc.frameTime) + " s; raise sim.max_substeps or sim.cfl, shorten "
                         "sim.frame_time, or weaken what drives the flow (gravity × thermal_expansion × the "
                         "sources' temperature excess, jet velocities) or add viscosity");
}

}  // namespace eikon::sim
