// The optical fields of a scene, frame after frame: the medium and objects
// voxelized once, or — when the scene has a `sim` section — the fluid
// solver's fields with the objects composited over them, advanced one frame
// at a time. Fields are validated as they leave here, toward the renderer.
#pragma once

#include "bridge/grid/FieldSet.h"
#include "bridge/io/ExportArrays.h"
#include "bridge/scene/Scene.h"
#include "sim/fluid/FluidSimulation.h"

#include <memory>
#include <vector>

namespace eikon::sim {

class SceneFields {
public:
    explicit SceneFields(const Scene& scene);

    const FieldSet& fields() const { return fields_; }
    bool changesOverTime() const { return fluid_ != nullptr; }
    // Simulated time of the current fields, s (0 without a simulation).
    double time() const { return fluid_ ? fluid_->time() : 0.0; }
    // Advances the simulation by one frame and refreshes the fields; a
    // static scene stays as it is.
    void advanceFrame();
    // Phase timings of the last simulated frame (empty without a simulation).
    std::vector<PhaseTiming> lastTimings() const;
    // The simulation's own fields on the render grid, for export (empty for a
    // static scene): velocity, temperature, concentration, dye.
    std::vector<io::NamedArray> exportArrays() const;

private:
    void refreshFromSimulation();

    Scene scene_;
    FieldSet fields_;
    std::unique_ptr<FluidSimulation> fluid_;
};

}  // namespace eikon::sim
