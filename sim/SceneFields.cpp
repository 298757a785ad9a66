#include "sim/SceneFields.h"

#include "sim/voxelize/AnalyticVoxelizer.h"
#include "sim/voxelize/VolumePainter.h"

#include "bridge/core/Error.h"

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

void SceneFields::simulateFrame() {
    if (fluid_) fluid_->advanceFrame();
}

void SceneFields::writeFrameInto(const FieldViews& target) const {
    EIKON_CHECK_MSG(fluid_, "only a simulated scene writes frames into GPU memory");
    FieldViews frame = target;
    frame.referenceIndex = fields_.referenceIndex;
    fluid_->writeFields(frame);
    paintObjects(scene_, frame);
    paintStrokes(scene_, frame);
    validateFields(frame, scene_.sourcePath);
}

std::vector<PhaseTiming> SceneFields::lastTimings() const {
    return fluid_ ? fluid_->lastTimings() : std::vector<PhaseTiming>{};
}

// The solver writes the medium (bumping the versions of what changed), then
// the objects are composited over it again.
void SceneFields::refreshFromSimulation() {
    fluid_->writeFields(fields_);
    paintObjects(scene_, fields_);
    paintStrokes(scene_, fields_);
}

}  // namespace eikon::sim
