#include "sim/SceneFields.h"

#include "sim/fluid/SolverExport.h"
#include "sim/voxelize/AnalyticVoxelizer.h"

namespace eikon::sim {

SceneFields::SceneFields(const Scene& scene) : scene_(scene), fields_(voxelizeScene(scene)) {
    if (scene.sim) {
        fluid_ = std::make_unique<FluidSimulation>(*scene.sim, fields_.grid, fields_.referenceIndex);
        refreshFromSimulation();
    }
    validateFields(fields_, scene.sourcePath);
}

void SceneFields::advanceFrame() {
    if (!fluid_) return;
    fluid_->advanceFrame();
    refreshFromSimulation();
}

std::vector<PhaseTiming> SceneFields::lastTimings() const {
    return fluid_ ? fluid_->lastTimings() : std::vector<PhaseTiming>{};
}

std::vector<io::NamedArray> SceneFields::exportArrays() const {
    if (!fluid_) return {};
    return solverArrays(fluid_->state(), fields_.grid, scene_.sim->ambientTemperature);
}

// The solver writes the medium (bumping the versions of what changed), then
// the objects are composited over it again.
void SceneFields::refreshFromSimulation() {
    fluid_->writeFields(fields_);
    paintObjects(scene_, fields_);
}

}  // namespace eikon::sim
