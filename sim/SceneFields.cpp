#include "sim/SceneFields.h"

#include "sim/deform/AnimatedMesh.h"
#include "sim/fluid/SolverExport.h"
#include "sim/voxelize/Compositor.h"
#include "sim/voxelize/MeshCoverage.h"
#include "sim/voxelize/VolumePainter.h"

#include "bridge/core/Error.h"

#include <algorithm>
#include <chrono>

namespace eikon::sim {

struct SceneFields::MeshObject {
    std::size_t object;  // index into scene.objects
    AnimatedMesh shape;
    MeshCoverage coverage;
    CellBlocks changed;  // cells whose coverage the last update recomputed
    int layer;           // its layer of fields().surfaceDistance when its surface is sharp, else −1
};

namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

SceneFields::SceneFields(const Scene& scene) : scene_(scene) {
    fields_.grid = scene.grid.spec();
    fields_.referenceIndex = scene.medium.index;
    fields_.deltaIndex.assign(fields_.grid.cellCount(), 0.0f);
    int layers = 0;
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        const ObjectDesc& object = scene.objects[o];
        if (object.kind != ObjectDesc::Kind::Mesh && object.kind != ObjectDesc::Kind::Water) continue;
        const std::string where = scene.sourcePath + ": objects[" + std::to_string(o) + "]";
        const int layer = object.hasDistanceSurface() ? layers++ : -1;
        meshes_.push_back(std::unique_ptr<MeshObject>(new MeshObject{
            o, AnimatedMesh(object, where), MeshCoverage(fields_.grid), CellBlocks(fields_.grid), layer}));
    }
    fields_.surfaceDistance.resize(static_cast<std::size_t>(layers) * fields_.grid.cellCount());
    fields_.surfaceBounds.resize(static_cast<std::size_t>(layers) * kSurfaceBoundsFloats);
    for (const auto& mesh : meshes_)  // far from the surface, before any update: the band's edge
        if (mesh->layer >= 0)
            std::copy(mesh->coverage.distances().begin(), mesh->coverage.distances().end(),
                      fields_.surfaceDistance.begin() + static_cast<std::ptrdiff_t>(mesh->layer) *
                                                            static_cast<std::ptrdiff_t>(fields_.grid.cellCount()));
    updateMeshes();
    fillMedium(scene_, fields_, CellBox::whole(fields_.grid));
    if (scene.sim) {
        fluid_ = std::make_unique<FluidSimulation>(*scene.sim, fields_.grid);
        fluidOptics_ = std::make_unique<OpticalModel>(*scene.sim);
        refreshFromSimulation();
    } else if (scene.volume) {
        volume_ = std::make_unique<VolumeSequence>(*scene.volume, scene.medium, fields_.grid);
        refreshFromSimulation();
    } else {
        paintObjects(scene_, fields_, coverageGrids());
        paintStrokes(scene_, fields_);
    }
    fields_.indexVersion = fields_.extinctionVersion = fields_.scatteringVersion = fields_.surfaceVersion = 1;
    validateFields(fields_, scene.sourcePath);
}

SceneFields::~SceneFields() = default;

bool SceneFields::changesOverTime() const {
    if (fluid_ || (volume_ && volume_->isSequence())) return true;
    for (const auto& mesh : meshes_)
        if (mesh->shape.changesOverTime()) return true;
    return false;
}

std::vector<const TriangleMesh*> SceneFields::deformedMeshes() const {
    std::vector<const TriangleMesh*> meshes;
    for (const auto& mesh : meshes_) meshes.push_back(&mesh->shape.mesh());
    return meshes;
}

// Deform, then voxelize: each object's coverage is redone only where its
// surface moved.
void SceneFields::updateMeshes() {
    deformMs_ = voxelizeMs_ = 0.0;
    recomputedCells_ = 0;
    for (auto& mesh : meshes_) {
        auto start = std::chrono::steady_clock::now();
        mesh->shape.advanceTo(time());
        deformMs_ += millisecondsSince(start);
        start = std::chrono::steady_clock::now();
        mesh->changed = mesh->coverage.update(mesh->shape.mesh());
        publishSurface(*mesh);
        voxelizeMs_ += millisecondsSince(start);
        recomputedCells_ += mesh->coverage.lastRecomputedCells();
    }
}

// A sharp mesh's φ into its layer, where it changed, and its bounds.
void SceneFields::publishSurface(const MeshObject& mesh) {
    if (mesh.layer < 0 || mesh.changed.empty()) return;
    const std::size_t cells = fields_.grid.cellCount();
    float* layer = fields_.surfaceDistance.data() + static_cast<std::size_t>(mesh.layer) * cells;
    const std::vector<float>& distances = mesh.coverage.distances();
    for (const CellBox& box : mesh.changed.boxes())
        for (int k = box.min.z; k < box.max.z; ++k)
            for (int j = box.min.y; j < box.max.y; ++j) {
                const std::size_t row = fields_.grid.linearIndex(box.min.x, j, k);
                std::copy_n(distances.begin() + static_cast<std::ptrdiff_t>(row), box.max.x - box.min.x, layer + row);
            }
    glm::dvec3 min, max;
    mesh.coverage.distanceBounds(min, max);
    float* bounds = fields_.surfaceBounds.data() + static_cast<std::size_t>(mesh.layer) * kSurfaceBoundsFloats;
    for (int axis = 0; axis < 3; ++axis) {
        bounds[axis] = static_cast<float>(min[axis]);
        bounds[3 + axis] = static_cast<float>(max[axis]);
    }
    ++fields_.surfaceVersion;
}

void SceneFields::advanceFrame() {
    if (!changesOverTime()) return;
    if (fluid_) {
        fluid_->advanceFrame();
    } else if (volume_ && volume_->isSequence()) {
        volume_->advanceFrame();
    } else {
        time_ += scene_.frameTime;
    }
    updateMeshes();
    if (fluid_ || volume_) {
        refreshFromSimulation();
        return;
    }
    CellBlocks changed(fields_.grid);
    for (const auto& mesh : meshes_) changed.add(mesh->changed);
    if (changed.empty()) return;
    const auto start = std::chrono::steady_clock::now();
    const CoverageGrids grids = coverageGrids();
    for (const CellBox& box : changed.boxes()) {
        fillMedium(scene_, fields_, box);
        paintObjects(scene_, fields_, grids, &box);
        paintStrokes(scene_, fields_, &box);
    }
    voxelizeMs_ += millisecondsSince(start);
    ++fields_.indexVersion;
    if (fields_.hasExtinction()) ++fields_.extinctionVersion;
    if (fields_.hasScattering()) ++fields_.scatteringVersion;
}

std::vector<PhaseTiming> SceneFields::lastTimings() const {
    std::vector<PhaseTiming> timings = fluid_ ? fluid_->lastTimings() : std::vector<PhaseTiming>{};
    if (!meshes_.empty()) {
        timings.push_back({"deform", deformMs_, 0, 0.0});
        timings.push_back({"voxelize", voxelizeMs_, static_cast<int>(std::min<long long>(recomputedCells_, 2147483647LL)), 0.0});
    }
    return timings;
}

// The solver or the volume writes the medium (bumping the versions of what
// changed), then the objects and strokes are composited over it again.
void SceneFields::refreshFromSimulation() {
    if (fluid_) writeOpticalFields(*fluidOptics_, fluid_->scalars(), fields_);
    else volume_->writeFields(fields_);
    paintObjects(scene_, fields_, coverageGrids());
    paintStrokes(scene_, fields_);
    validateFields(fields_, volume_ ? volume_->currentFile() : scene_.sourcePath);
}

std::vector<NamedArray> SceneFields::exportArrays() const {
    if (volume_) return volume_->exportArrays();
    if (!fluid_) return {};
    return solverArrays(fluid_->state(), fields_.grid, scene_.sim->ambientTemperature);
}

CoverageGrids SceneFields::coverageGrids() const {
    CoverageGrids grids(scene_.objects.size(), nullptr);
    for (const auto& mesh : meshes_) grids[mesh->object] = &mesh->coverage.values();
    return grids;
}

void SceneFields::simulateFrame() {
    EIKON_CHECK_MSG(fluid_, "only a scene with a fluid solver writes its frames into GPU memory");
    fluid_->advanceFrame();
    updateMeshes();
}

void SceneFields::writeFrameInto(const FieldViews& target) const {
    EIKON_CHECK_MSG(fluid_, "only a scene with a fluid solver writes its frames into GPU memory");
    FieldViews frame = target;
    frame.referenceIndex = fields_.referenceIndex;
    EIKON_CHECK_MSG(frame.grid.resolution == fields_.grid.resolution, "field views on another grid");
    EIKON_CHECK_MSG((frame.hasExtinction() || !fluidOptics_->absorbs()) &&
                        (frame.hasScattering() || !fluidOptics_->scatters()),
                    "field views without the fields the optical model writes");
    EIKON_CHECK_MSG(frame.surfaceDistance.size() == fields_.surfaceDistance.size() &&
                        frame.surfaceBounds.size() == fields_.surfaceBounds.size(),
                    "field views without the scene's sharp surface layers");
    std::copy(fields_.surfaceDistance.begin(), fields_.surfaceDistance.end(), frame.surfaceDistance.begin());
    std::copy(fields_.surfaceBounds.begin(), fields_.surfaceBounds.end(), frame.surfaceBounds.begin());
    mapOpticalFields(*fluidOptics_, fluid_->scalars(), frame);
    paintObjects(scene_, frame, coverageGrids());
    paintStrokes(scene_, frame);
    validateFields(frame, scene_.sourcePath);
}

}  // namespace eikon::sim
