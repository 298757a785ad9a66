#include "sim/SceneFields.h"

#include "sim/FieldOrigins.h"
#include "sim/SharpMeshSurfaces.h"
#include "sim/deform/AnimatedMesh.h"
#include "sim/fluid/SolverExport.h"
#include "sim/voxelize/Compositor.h"
#include "sim/voxelize/HeightFieldCoverage.h"
#include "sim/voxelize/MeshCoverage.h"
#include "sim/voxelize/VolumePainter.h"

#include "bridge/core/Error.h"
#include "bridge/mesh/Creases.h"

#include <algorithm>
#include <chrono>
#include <optional>

namespace eikon::sim {

struct SceneFields::MeshObject {
    std::size_t object;  // index into scene.objects
    AnimatedMesh shape;
    // Its coverage: a mesh's from its narrow-band distance, a water body's
    // in closed form from its height field.
    std::optional<MeshCoverage> meshCoverage;
    std::optional<HeightFieldCoverage> waterCoverage;
    CellBlocks changed;  // cells whose coverage the last update recomputed

    const std::vector<float>& coverage() const {
        return waterCoverage ? waterCoverage->values() : meshCoverage->values();
    }
    // Brings the coverage up to the shape's current frame.
    void updateCoverage() {
        if (const WaterSurface* water = shape.water()) {
            const WaterDesc& desc = water->desc();
            changed = waterCoverage->update({desc.basinMin, desc.basinMax, desc.cells, &water->heights()});
        } else {
            changed = meshCoverage->update(shape.mesh());
        }
    }
    long long lastRecomputedCells() const {
        return waterCoverage ? waterCoverage->lastRecomputedCells() : meshCoverage->lastRecomputedCells();
    }
    // When its surface is sharp: its triangles for the tracers, and where
    // they go in fields().surfaceNodes and surfaceTriangles.
    std::unique_ptr<SharpMeshSurface> surface;
    std::size_t root = 0, firstNode = 0, firstTriangle = 0;
    bool published = false;
    bool coverageBehind = false;  // a sharp surface's coverage, not kept: it lags the shape
};

namespace {

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// Runs `work` of the fluid solver, whose refusals and breakdowns name key
// paths and its own cells, not the file: they are told the scene file.
template <typename Work>
void inSceneFile(const Scene& scene, Work&& work) {
    try {
        work();
    } catch (const InputError& error) {
        throw InputError(scene.sourcePath + ": " + error.what());
    } catch (const NumericalBreakdown& error) {
        throw NumericalBreakdown(scene.sourcePath + ": " + error.what());
    }
}

}  // namespace

bool SceneFields::needsSharpCoverage(const Scene& scene) {
    return scene.render.method != RenderDesc::Method::ImageSpace || scene.exports.vtk.enabled || scene.exports.vdb.enabled;
}

SceneFields::SceneFields(const Scene& scene) : scene_(scene), keepSharpCoverage_(needsSharpCoverage(scene)) {
    fields_.grid = scene.grid.spec();
    fields_.referenceIndex = scene.medium.index;
    fields_.deltaIndex.assign(fields_.grid.cellCount(), 0.0f);
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        const ObjectDesc& object = scene.objects[o];
        if (object.kind != ObjectDesc::Kind::Mesh && object.kind != ObjectDesc::Kind::Water) continue;
        const std::string where = scene.sourcePath + ": objects[" + std::to_string(o) + "]";
        meshes_.push_back(std::unique_ptr<MeshObject>(
            new MeshObject{o, AnimatedMesh(object, where), std::nullopt, std::nullopt, CellBlocks(fields_.grid), {}}));
        if (meshes_.back()->shape.water()) meshes_.back()->waterCoverage.emplace(fields_.grid);
        else meshes_.back()->meshCoverage.emplace(fields_.grid);
        if (object.hasTriangleSurface())
            meshes_.back()->surface = std::make_unique<SharpMeshSurface>(meshes_.back()->shape.mesh());
    }
    // The roots first (node k: the k-th sharp mesh), then each tree's other
    // nodes. The water bodies' triangles come after the other meshes': image
    // space draws those alone (render/stages/SurfaceLayers.h).
    const auto roots = static_cast<std::size_t>(
        std::count_if(meshes_.begin(), meshes_.end(), [](const auto& mesh) { return mesh->surface != nullptr; }));
    std::size_t root = 0, nodes = roots, triangles = 0;
    for (auto& mesh : meshes_) {
        if (!mesh->surface) continue;
        mesh->root = root++;
        mesh->firstNode = nodes;
        nodes += mesh->surface->nodeCount() - 1;
    }
    for (const bool water : {false, true})
        for (auto& mesh : meshes_) {
            if (!mesh->surface || (mesh->shape.water() != nullptr) != water) continue;
            mesh->firstTriangle = triangles;
            triangles += mesh->surface->triangleCount();
        }
    fields_.surfaceNodes.resize(nodes * kSurfaceNodeFloats);
    fields_.surfaceTriangles.resize(triangles * kSurfaceTriangleFloats);
    updateMeshes();
    fillMedium(scene_, fields_, CellBox::whole(fields_.grid));
    if (scene.sim) {
        inSceneFile(scene, [&] { fluid_ = std::make_unique<FluidSimulation>(*scene.sim, fields_.grid); });
        fluidOptics_ = std::make_unique<OpticalModel>(*scene.sim);
        refreshFromSimulation();
    } else if (scene.volume) {
        volume_ = std::make_unique<VolumeSequence>(*scene.volume, scene.medium, fields_.grid, scene.sourcePath);
        refreshFromSimulation();
    } else {
        paintObjects(scene_, fields_, coverageGrids());
        paintStrokes(scene_, fields_);
    }
    fields_.indexVersion = fields_.extinctionVersion = fields_.scatteringVersion = fields_.surfaceVersion = 1;
    validateFields(fields_, sceneFieldOrigin(scene_, volume_ ? volume_->currentFile() : ""));
}

SceneFields::~SceneFields() = default;

std::string SceneFields::placeFluidSolver(bool hardwareGpu) {
    if (!fluid_) return "";
    if (runsOnGpu(scene_.sim->device, hardwareGpu)) {
        auto backend = std::make_unique<gpu::GpuFluidBackend>(*fluid_);
        gpuSolver_ = backend.get();
        fluid_->attachDevice(std::move(backend));
        gpuOptics_ = std::make_unique<gpu::GpuOpticalMapping>(*scene_.sim, fluid_->solverGrid(), fields_.grid,
                                                              fields_.referenceIndex);
    }
    return fluid_->deviceName();
}

SceneFields::MeshObject* SceneFields::waterObject() const {
    const auto water = std::find_if(meshes_.begin(), meshes_.end(), [](const auto& mesh) { return mesh->shape.water(); });
    return water == meshes_.end() ? nullptr : water->get();
}

std::string SceneFields::placeWater(bool hardwareGpu) {
    MeshObject* const water = waterObject();
    if (!water) return "";
    const ObjectDesc& object = scene_.objects[water->object];
    if (!runsOnGpu(object.water.device, hardwareGpu)) return "cpu";
    const std::string unfit = gpu::GpuWaterBody::unfit(scene_);
    if (!unfit.empty()) {
        if (object.water.device == ComputeDevice::Auto) return "cpu";
        throw InputError(scene_.sourcePath + ": objects[" + std::to_string(water->object) + "].device",
                         "\"cpu\" or \"auto\" (the water stays on the GPU only as the scene's only object, sharp, "
                         "under no solver, volume, paint or field export)",
                         "\"gpu\", but " + unfit);
    }
    FieldSet medium;
    medium.grid = fields_.grid;
    medium.referenceIndex = fields_.referenceIndex;
    medium.deltaIndex.assign(fields_.grid.cellCount(), 0.0f);
    fillMedium(scene_, medium, CellBox::whole(medium.grid));
    const SharpMeshSurface& surface = *water->surface;
    gpuWater_ = std::make_unique<gpu::GpuWaterBody>(
        object, *water->shape.water(),
        gpu::SharpSurfaceTopology{surface.bvh(), surface.cornerStart(), surface.cornerTriangles(),
                                  creaseCosine()},
        fields_, medium);
    return "gpu";
}

std::string SceneFields::waterDevice() const {
    if (gpuWater_) return "gpu";
    return waterObject() ? "cpu" : "";
}

void SceneFields::writeFrameOnGpu(const gpu::OpticalTargets& targets) const {
    EIKON_CHECK_MSG(mapsOnGpu(), "the optical mapping runs on the GPU only with the solver there and nothing over it");
    gpuOptics_->map(gpuSolver_->temperature(), gpuSolver_->concentration(), gpuSolver_->dye(), targets);
}

bool SceneFields::changesOverTime() const {
    if (fluid_ || (volume_ && volume_->isSequence())) return true;
    for (const auto& mesh : meshes_)
        if (mesh->shape.changesOverTime()) return true;
    return false;
}

bool SceneFields::framesAreIndependent() const {
    if (fluid_ || (volume_ && volume_->following())) return false;
    for (const auto& mesh : meshes_)
        if (mesh->shape.changesOverTime()) return false;
    return true;
}

void SceneFields::seekFrame(int frame) {
    EIKON_CHECK_MSG(framesAreIndependent(), "seekFrame in a scene whose frames depend on each other");
    if (!volume_ || !volume_->isSequence()) return;  // a static scene: every frame is the same
    volume_->seekFrame(frame);
    refreshFromSimulation();
}

std::vector<const TriangleMesh*> SceneFields::deformedMeshes() const {
    std::vector<const TriangleMesh*> meshes;
    for (const auto& mesh : meshes_) meshes.push_back(&mesh->shape.mesh());
    return meshes;
}

// Deform, then voxelize: each object's coverage is redone only where its
// surface moved (a sharp surface's only while its coverage is kept).
void SceneFields::updateMeshes() {
    deformMs_ = voxelizeMs_ = 0.0;
    recomputedCells_ = 0;
    for (auto& mesh : meshes_) {
        auto start = std::chrono::steady_clock::now();
        mesh->shape.advanceTo(time());
        deformMs_ += millisecondsSince(start);
        start = std::chrono::steady_clock::now();
        if (mesh->surface && !keepSharpCoverage_) {
            mesh->coverageBehind = mesh->coverageBehind || !mesh->published || mesh->shape.changesOverTime();
            mesh->changed = CellBlocks(fields_.grid);
            publishSurface(*mesh, mesh->shape.changesOverTime());
        } else {
            mesh->updateCoverage();
            publishSurface(*mesh, !mesh->changed.empty());
            recomputedCells_ += mesh->lastRecomputedCells();
        }
        voxelizeMs_ += millisecondsSince(start);
    }
}

void SceneFields::keepSharpCoverage(bool keep) {
    if (keep == keepSharpCoverage_) return;
    keepSharpCoverage_ = keep;
    if (!keep) return;
    if (gpuWater_) {  // no step: the surface and its coverage at the current time
        voxelizeMs_ += gpuWater_->advanceTo(time_, true).coverage;
        if (fields_.hasExtinction()) ++fields_.extinctionVersion;
        if (fields_.hasScattering()) ++fields_.scatteringVersion;
        return;
    }
    const auto start = std::chrono::steady_clock::now();
    for (auto& mesh : meshes_) {
        if (!mesh->coverageBehind) continue;
        mesh->updateCoverage();
        mesh->coverageBehind = false;
    }
    if (fluid_ || volume_) refreshFromSimulation();
    else repaintWhereMeshesChanged();
    voxelizeMs_ += millisecondsSince(start);
}

// A sharp mesh's tree and triangles, refitted when its vertices moved
// within the grid (the tracers see no surface outside it).
void SceneFields::publishSurface(MeshObject& mesh, bool moved) {
    if (!mesh.surface || (mesh.published && !moved)) return;
    mesh.published = true;
    mesh.surface->write(mesh.shape.mesh(), mesh.root, mesh.firstNode, mesh.firstTriangle, fields_.surfaceNodes.data(),
                        fields_.surfaceTriangles.data());
    ++fields_.surfaceVersion;
}

void SceneFields::advanceFrame() {
    if (!changesOverTime()) return;
    if (fluid_) {
        inSceneFile(scene_, [&] { fluid_->advanceFrame(); });
    } else if (volume_ && volume_->isSequence()) {
        volume_->advanceFrame();
    } else {
        time_ = static_cast<double>(++frame_) * scene_.frameTime;  // one rounding: no drift over frames
    }
    if (gpuWater_) {  // the scene's only object: nothing is left for the host
        const gpu::GpuWaterBody::PassTimes times = gpuWater_->advanceTo(time_, keepSharpCoverage_);
        deformMs_ = times.surface;
        voxelizeMs_ = times.coverage;
        recomputedCells_ = keepSharpCoverage_ ? static_cast<long long>(fields_.grid.cellCount()) : 0;
        ++fields_.surfaceVersion;
        if (keepSharpCoverage_) {
            if (fields_.hasExtinction()) ++fields_.extinctionVersion;
            if (fields_.hasScattering()) ++fields_.scatteringVersion;
        }
        return;
    }
    updateMeshes();
    if (fluid_ || volume_) {
        refreshFromSimulation();
        return;
    }
    repaintWhereMeshesChanged();
}

// The medium, objects and strokes again over the cells whose coverage the
// meshes' last update changed.
void SceneFields::repaintWhereMeshesChanged() {
    CellBlocks changed(fields_.grid);
    for (const auto& mesh : meshes_) changed.add(mesh->changed);
    if (changed.empty()) return;
    const auto start = std::chrono::steady_clock::now();
    const CoverageGrids grids = coverageGrids();
    CellBox repainted;
    for (const CellBox& box : changed.boxes()) {
        fillMedium(scene_, fields_, box);
        paintObjects(scene_, fields_, grids, &box);
        paintStrokes(scene_, fields_, &box);
        repainted = repainted.unite(box);
    }
    voxelizeMs_ += millisecondsSince(start);
    // The GPU's copies need only the repainted cells (their bounding box).
    fields_.indexChange = {++fields_.indexVersion, repainted};
    if (fields_.hasExtinction()) fields_.extinctionChange = {++fields_.extinctionVersion, repainted};
    if (fields_.hasScattering()) fields_.scatteringChange = {++fields_.scatteringVersion, repainted};
}

std::vector<PhaseTiming> SceneFields::lastTimings() const {
    std::vector<PhaseTiming> timings = fluid_ ? fluid_->lastTimings() : std::vector<PhaseTiming>{};
    if (!meshes_.empty()) {
        timings.push_back({"deform", deformMs_, 0, 0.0});
        timings.push_back({"voxelize", voxelizeMs_, static_cast<int>(std::min<long long>(recomputedCells_, 2147483647LL)), 0.0});
    }
    return timings;
}

std::optional<FluidFrameReport> SceneFields::fluidReport() const {
    if (!fluid_) return std::nullopt;
    return fluid_->lastReport();
}

// The solver or the volume writes the medium (bumping the versions of what
// changed), then the objects and strokes are composited over it again.
void SceneFields::refreshFromSimulation() {
    if (fluid_) writeOpticalFields(*fluidOptics_, fluid_->scalars(), fields_);
    else volume_->writeFields(fields_);
    paintObjects(scene_, fields_, coverageGrids());
    paintStrokes(scene_, fields_);
    validateFields(fields_, sceneFieldOrigin(scene_, volume_ ? volume_->currentFile() : ""));
}

VolumeDesc SceneFields::callerOptics(std::optional<VolumeDesc::TemperatureUnit> temperatureUnit) const {
    VolumeDesc optics = scene_.volume ? *scene_.volume : VolumeDesc{};
    if (temperatureUnit) {  // declared, as by volume.fields.temperature_unit
        optics.temperatureUnit = *temperatureUnit;
        optics.implicitTemperatureUnit = false;
    }
    // A refusal names the caller's fields by the names they were handed as.
    optics.indexGrid = "index";
    optics.deltaIndexGrid = "delta_index";
    optics.extinctionGrid = "extinction";
    optics.scatteringGrid = "scattering";
    optics.anisotropyGrid = "anisotropy";
    optics.emissionGrid = "emission";
    optics.massFractions.clear();  // a caller hands no gas density, so no mixture
    return optics;
}

void SceneFields::writeCallerFields(const VolumeSamples& samples, const std::string& origin,
                                    std::optional<VolumeDesc::TemperatureUnit> temperatureUnit) {
    EIKON_CHECK_MSG(!fluid_, "a scene with a fluid solver makes its own fields");
    const VolumeDesc optics = callerOptics(temperatureUnit);
    writeVolumeOptics(optics, scene_.medium, samples, {scene_.sourcePath, origin}, fields_);
    paintObjects(scene_, fields_, coverageGrids());
    paintStrokes(scene_, fields_);
    validateFields(fields_, sceneFieldOrigin(scene_, origin));
}

std::vector<NamedArray> SceneFields::exportArrays(const std::vector<std::string>& names) const {
    if (volume_) return volume_->exportArrays();
    if (!fluid_) return {};
    auto wants = [&](const char* name) {
        return names.empty() || std::find(names.begin(), names.end(), name) != names.end();
    };
    // The const state(): reading it must not mark the host copy newer (a
    // solver on the GPU would take the whole state back before its next substep).
    const FluidSimulation& fluid = *fluid_;
    if (wants("velocity")) return solverArrays(fluid.state(), fields_.grid, *scene_.sim, names);
    if (!wants("temperature") && !wants("concentration") && !wants("dye")) return {};
    return solverArrays(fluid.scalarState(), fields_.grid, *scene_.sim, names);
}

CoverageGrids SceneFields::coverageGrids() const {
    CoverageGrids grids(scene_.objects.size(), nullptr);
    for (const auto& mesh : meshes_) grids[mesh->object] = &mesh->coverage();
    return grids;
}

void SceneFields::simulateFrame() {
    EIKON_CHECK_MSG(fluid_, "only a scene with a fluid solver writes its frames into GPU memory");
    inSceneFile(scene_, [&] { fluid_->advanceFrame(); });
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
    EIKON_CHECK_MSG(frame.surfaceNodes.size() == fields_.surfaceNodes.size() &&
                        frame.surfaceTriangles.size() == fields_.surfaceTriangles.size(),
                    "field views without the scene's sharp surfaces");
    std::copy(fields_.surfaceNodes.begin(), fields_.surfaceNodes.end(), frame.surfaceNodes.begin());
    std::copy(fields_.surfaceTriangles.begin(), fields_.surfaceTriangles.end(), frame.surfaceTriangles.begin());
    mapOpticalFields(*fluidOptics_, fluid_->scalars(), frame);
    paintObjects(scene_, frame, coverageGrids());
    paintStrokes(scene_, frame);
    validateFields(frame, sceneFieldOrigin(scene_));
}

}  // namespace eikon::sim
