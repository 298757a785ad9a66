#include "sim/SceneFields.h"

#include "sim/fluid/SolverExport.h"
#include "sim/voxelize/AnalyticVoxelizer.h"

namespace eikon::sim {

SceneFields::SceneFields(const Scene& scene) : scene_(scene), fields_(voxelizeScene(scene)) {
    if (scene.sim) {
        fluid_ = std::make_unique<FluidSimulation>(*scene.sim, fields_.grid, fields_.referenceIndex);
        refreshFromSimulation();
    } else if (scene.volume) {
        volume_ = std::make_unique<VolumeSequence>(*scene.volume, scene.medium, fields_.grid);
        refreshFromSimulation();
    }
    validateFields(fields_, scene.sourcePath);
}

void SceneFields::advanceFrame() {
    if (fluid_) fluid_->advanceFrame();
    else if (volume_ && volume_->isSequence()) volume_->advanceFrame();
    else return;
    refreshFromSimulation();
}

std::vector<PhaseTiming> SceneFields::lastTimings() const {
    return fluid_ ? fluid_->lastTimings() : std::vector<PhaseTiming>{};
}

std::vector<io::NamedArray> SceneFields::exportArrays() const {
    if (volume_) return volume_->exportArrays();
    if (!fluid_) return {};
    return solverArrays(fluid_->state(), fields_.grid, scene_.sim->ambientTemperature);
}

// The solver or the volume writes the medium (bumping the versions of what
// changed), then the objects are composited over it again.
void SceneFields::refreshFromSimulation() {
    if (fluid_) fluid_->writeFields(fields_);
    else volume_->writeFields(fields_);
    paintObjects(scene_, fields_);
    validateFields(fields_, volume_ ? volume_->currentFile() : scene_.sourcePath);
}

}  // namespace eikon::sim
