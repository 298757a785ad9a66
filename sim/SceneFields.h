// The optical fields of a scene, frame after frame: the medium and objects
// voxelized once, or — when the scene has a `sim` section — the fluid
// solver's fields with the objects composited over them, advanced one frame
// at a time, or — with a `volume` — an OpenVDB file or sequence stepped one
// file per frame, objects composited over it. Fields are validated as they leave here, toward the renderer.
#pragma once

#include "bridge/grid/FieldSet.h"
#include "bridge/io/ExportArrays.h"
#include "bridge/scene/Scene.h"
#include "sim/fluid/FluidSimulation.h"
#include "sim/volume/VolumeSequence.h"

#include <memory>
#include <vector>

namespace eikon::sim {

class SceneFields {
public:
    explicit SceneFields(const Scene& scene);

    const FieldSet& fields() const { return fields_; }
    bool changesOverTime() const { return fluid_ != nullptr || (volume_ && volume_->isSequence()); }
    // Simulated time of the current fields, s (0 without a simulation or volume).
    double time() const { return fluid_ ? fluid_->time() : volume_ ? volume_->time() : 0.0; }
    // Advances the simulation by one frame and refreshes the fields; a
    // static scene stays as it is.
    void advanceFrame();
    // Phase timings of the last simulated frame (empty without a simulation).
    std::vector<PhaseTiming> lastTimings() const;
    // The simulation's own fields on the render grid, for export (empty for a
    // static scene): velocity, temperature, concentration, dye; a volume's
    // density, temperature, flame, velocity.
    std::vector<io::NamedArray> exportArrays() const;

private:
    void refreshFromSimulation();

    Scene scene_;
    FieldSet fields_;
    std::unique_ptr<FluidSimulation> fluid_;
    std::unique_ptr<VolumeSequence> volume_;
};

}  // namespace eikon::sim
