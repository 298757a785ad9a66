// `eikon bench`'s per-kernel figures: each stage's wall time (median over
// full frames in which every field is new, so every stage runs again)
// beside the count of what it worked on, taken from the frame's own figures
// — photons traced and their march steps, the wavefront's rays and patches,
// grid cells, camera rays, pixels — and the time per unit. A stage that did
// not run (a uniform medium needs no gradient or step structure) says why.
#pragma once

#include "bridge/grid/FieldSet.h"
#include "bridge/scene/Scene.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace eikon::app {

struct KernelFigure {
    std::string kernel;       // the frame report's stage name
    std::string unit;         // photon, ray, patch, step, cell, camera ray, pixel, frame
    std::string device;       // "gpu" (compute shaders) or "cpu" (native loops), as the report says
    std::uint64_t count = 0;  // units of work in one frame
    double milliseconds = 0.0;
    bool measured = true;  // false: the stage did not run, or its time was not resolved
    std::string reason;    // why not

    double nanosecondsPerUnit() const { return count > 0 ? milliseconds * 1e6 / static_cast<double>(count) : 0.0; }
};

// The median of `values` (the upper one of an even count), as every bench
// figure is taken.
double median(std::vector<double> values);

// Renders one frame (compilation, first uploads), then `repeats` frames in
// which every field's version moves on; one figure per stage and unit.
std::vector<KernelFigure> measureKernels(const Scene& scene, const FieldSet& fields, int repeats);

// The fluence tallies and their smoothing: the photon pass with
// tracer.store_fluence on less the pass without it (relight medians), per
// grid cell. A difference of two timings: one no larger than zero is
// reported as not resolved, and one between two devices (render.device
// "auto" may run one natively and not the other) as not measured; nor where
// the scene stores fluence either way.
struct Relight {
    double milliseconds = 0.0;
    std::string device;  // of the photon stage
};
KernelFigure fluenceFigure(std::uint64_t cells, bool storedEitherWay, const Relight& withFluence,
                           const Relight& withoutFluence);

void printKernels(const std::vector<KernelFigure>& figures);
nlohmann::json kernelsJson(const std::vector<KernelFigure>& figures);

}  // namespace eikon::app
