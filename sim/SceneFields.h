// The optical fields of a scene, frame after frame: the medium and objects
// voxelized once, or — when the scene has a `sim` section — the fluid
// solver's fields with the objects composited over them, advanced one frame
// at a time. Mesh and water objects move with scene time; only the cells
// their motion touched are recomputed. Fields are validated as they leave
// here, toward the renderer.
#pragma once

#include "bridge/grid/FieldSet.h"
#include "bridge/mesh/TriangleMesh.h"
#include "bridge/scene/Scene.h"
#include "sim/fluid/FluidSimulation.h"

#include <memory>
#include <vector>

namespace eikon::sim {

class SceneFields {
public:
    explicit SceneFields(const Scene& scene);
    ~SceneFields();

    const FieldSet& fields() const { return fields_; }
    bool changesOverTime() const;
    // Scene time of the current fields, s.
    double time() const { return fluid_ ? fluid_->time() : time_; }
    // Advances the simulation and the deforming objects by one frame and
    // refreshes the fields; a static scene stays as it is.
    void advanceFrame();
    // Phase timings of the last frame: the fluid solver's phases, then
    // "deform" and "voxelize" (iterations: cells recomputed) for scenes with
    // mesh or water objects.
    std::vector<PhaseTiming> lastTimings() const;
    // This frame's mesh of every mesh or water object, in scene order.
    std::vector<const TriangleMesh*> deformedMeshes() const;

private:
    struct MeshObject;
    void updateMeshes();
    void refreshFromSimulation();

    Scene scene_;
    FieldSet fields_;
    std::unique_ptr<FluidSimulation> fluid_;
    std::vector<std::unique_ptr<MeshObject>> meshes_;
    double time_ = 0.0;  // without a fluid solver
    double deformMs_ = 0.0;
    double voxelizeMs_ = 0.0;
    long long recomputedCells_ = 0;
};

}  // namespace eikon::sim
