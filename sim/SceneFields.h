// The optical fields of a scene, frame after frame: the medium and objects
// voxelized once; or the fluid solver's fields (a `sim` section) or an
// OpenVDB file or sequence (a `volume`, one file per frame) with the objects
// composited over them. Mesh and water objects move with scene time; without
// a solver or volume only the cells their motion touched are recomputed;
// the triangles of those whose surface is sharp are refitted into their
// trees (sim/SharpMeshSurfaces.h).
// Paint strokes go over everything. Fields are validated as they leave here,
// toward the renderer.
#pragma once

#include "bridge/grid/FieldSet.h"
#include "bridge/grid/FieldViews.h"
#include "bridge/grid/NamedArrays.h"
#include "bridge/mesh/TriangleMesh.h"
#include "bridge/scene/Scene.h"
#include "sim/fluid/FluidSimulation.h"
#include "sim/gpu/GpuFluidBackend.h"
#include "sim/gpu/GpuOpticalMapping.h"
#include "sim/gpu/GpuWaterBody.h"
#include "sim/optics/OpticalMapping.h"
#include "sim/volume/VolumeSequence.h"
#include "sim/voxelize/Compositor.h"

#include <memory>
#include <optional>
#include <vector>

namespace eikon::sim {

class SceneFields {
public:
    explicit SceneFields(const Scene& scene);
    ~SceneFields();

    const FieldSet& fields() const { return fields_; }
    bool changesOverTime() const;
    // Scene time of the current fields, s.
    double time() const { return fluid_ ? fluid_->time() : volume_ ? volume_->time() : time_; }
    // Advances the simulation and the deforming objects by one frame and
    // refreshes fields() (only the cells moving objects touched, without a
    // fluid solver); a static scene stays as it is.
    void advanceFrame();
    // The volume, when it follows a simulation as it writes (VolumeDesc::follow): its
    // next step is awaited there before advanceFrame; null otherwise.
    VolumeSequence* followedVolume() { return volume_ && volume_->following() ? volume_.get() : nullptr; }
    // Whether frame k's fields can be made without frames 0 … k−1: no fluid
    // solver and no moving mesh or water object (a static scene, or a volume
    // sequence with still objects over it).
    bool framesAreIndependent() const;
    // The fields of frame `frame` straight away, for such a scene: a volume
    // sequence loads that frame's file (as `frame` calls of advanceFrame
    // would, bit for bit).
    void seekFrame(int frame);

    // A frame of the caller's own fields (the library, include/eikon/eikon.h)
    // in place of a volume file's grids: `samples` are read where they lie,
    // mapped to δn, κ, σs, g, ε by the scene's `volume` optics (its keys, or
    // their defaults without a `volume` section; sim/optics/VolumeOptics.h),
    // and the objects and strokes are composited over them, as over a
    // volume file's frame. `origin` names them in a refusal (InputError as
    // writeVolumeOptics'), which leaves fields() as it was — but for one by
    // validateFields after the objects are composited, which leaves the
    // refused fields: render them not. Not for a scene with a fluid solver,
    // whose fields are its own. `temperatureUnit`: what samples.temperature
    // holds, declared by the caller (as volume.fields.temperature_unit);
    // none: as the scene's volume reads its temperature.
    void writeCallerFields(const VolumeSamples& samples, const std::string& origin,
                           std::optional<VolumeDesc::TemperatureUnit> temperatureUnit);
    // The `volume` optics the caller's fields are mapped by (writeCallerFields).
    VolumeDesc callerOptics(std::optional<VolumeDesc::TemperatureUnit> temperatureUnit) const;

    // The live loop's two halves of advanceFrame for a scene with a fluid
    // solver, whose fields go straight into GPU memory
    // (render/stages/FieldRing.h): simulateFrame() advances the solver and
    // the deforming objects — fields() then stays as it was — and
    // writeFrameInto() writes the current frame's fields into `target`, which
    // has the layout of fields() (same grid, same fields present), and
    // validates them. Both may run on a thread other than the renderer's.
    bool simulatesFluid() const { return fluid_ != nullptr; }
    // Moves the fluid solver onto the GPU where sim.device asks for it:
    // "gpu", or "auto" when `hardwareGpu` (the renderer's context is not a
    // software rasterizer). Call once, with that context current on the
    // thread that will advance the frames. Returns where the solver runs:
    // "cpu", "gpu", or "" without a solver.
    std::string placeFluidSolver(bool hardwareGpu);
    // Moves a water body onto the GPU (sim/gpu/GpuWaterBody.h) where its
    // `device` asks for it ("gpu", or "auto" when `hardwareGpu`) and the
    // scene allows it (GpuWaterBody::unfit; "gpu" where it does not is an
    // InputError at the water's key path). Call once, before the first
    // frame advances, with the renderer's context current on the thread
    // that advances the frames. From then on its frames' surfaces and
    // attenuation live in gpuWater()'s buffers, and fields() keeps frame 0's
    // (apps/common/FrameSource.h renders from those buffers). Returns where
    // the water runs: "cpu", "gpu", or "" without a water body.
    std::string placeWater(bool hardwareGpu);
    const gpu::GpuWaterBody* gpuWater() const { return gpuWater_.get(); }
    std::string waterDevice() const;
    // Where the solver runs, and the bytes it moved between host and GPU
    // since the last call.
    std::string fluidDevice() const { return fluid_ ? fluid_->deviceName() : ""; }
    std::uint64_t takeFluidBusBytes() { return fluid_ ? fluid_->takeBusBytes() : 0; }
    // Whether a frame's fields can be made on the GPU from the solver's own
    // buffers: the solver runs there and nothing is composited over its
    // fields on the host (no objects, no paint strokes).
    bool mapsOnGpu() const { return gpuSolver_ != nullptr && scene_.objects.empty() && scene_.paint.empty(); }
    // writeFrameInto for such a scene: the optical mapping on the GPU, into
    // the buffers of `targets` (GL thread). The solver's scalars are checked
    // finite after every phase, and map to a finite index > 0 (T stays
    // within its sources' and initial range: the limiter and the implicit
    // diffusion make no new extrema), so validateFields has nothing to find.
    void writeFrameOnGpu(const gpu::OpticalTargets& targets) const;
    void simulateFrame();
    void writeFrameInto(const FieldViews& target) const;
    // Whether κ (σs) values change from frame to frame (dye in the solver).
    bool extinctionChangesOverTime() const { return fluid_ && fluidOptics_->absorbs(); }
    bool scatteringChangesOverTime() const { return fluid_ && fluidOptics_->scatters(); }
    // Phase timings of the last frame: the fluid solver's phases, then
    // "deform" and "voxelize" (iterations: cells recomputed) for scenes with
    // mesh or water objects.
    std::vector<PhaseTiming> lastTimings() const;
    // The fluid solver's last frame (FrameReport.h); empty without a solver.
    std::optional<FluidFrameReport> fluidReport() const;
    // The simulation's own fields on the render grid, for export (empty for a
    // static scene): velocity, temperature, concentration, dye; a volume's
    // density, temperature, flame, velocity. A fluid solver's are only those
    // `names` lists (empty: all), and a solver on the GPU reads back only
    // what they need (the scalars alone unless the velocity is asked for).
    std::vector<NamedArray> exportArrays(const std::vector<std::string>& names = {}) const;
    // This frame's mesh of every mesh or water object, in scene order.
    std::vector<const TriangleMesh*> deformedMeshes() const;

    // Whether frames keep the voxel coverage of the sharp meshes and water
    // surfaces up to date, and the attenuation painted into the grid from
    // it: only the eikonal tracer and field exports read them, while image
    // space draws the surfaces themselves. Off, a frame deforms the shapes and
    // refits their triangles only (pool_caustics: 18 ms of coverage and 21 MB
    // of upload saved per frame); turned on, the coverage catches up with the
    // current frame. The constructor starts it as needsSharpCoverage says.
    void keepSharpCoverage(bool keep);
    static bool needsSharpCoverage(const Scene& scene);

private:
    struct MeshObject;
    MeshObject* waterObject() const;  // the scene's water body, or null
    void updateMeshes();
    void publishSurface(MeshObject& mesh, bool moved);
    void repaintWhereMeshesChanged();
    CoverageGrids coverageGrids() const;
    void refreshFromSimulation();

    Scene scene_;
    FieldSet fields_;
    std::unique_ptr<FluidSimulation> fluid_;
    std::unique_ptr<OpticalModel> fluidOptics_;  // the solver's scalars → δn, κ, σs
    gpu::GpuFluidBackend* gpuSolver_ = nullptr;  // the fluid's device, when it runs on the GPU
    std::unique_ptr<gpu::GpuOpticalMapping> gpuOptics_;
    std::unique_ptr<gpu::GpuWaterBody> gpuWater_;  // the water body, when it runs on the GPU
    std::unique_ptr<VolumeSequence> volume_;
    std::vector<std::unique_ptr<MeshObject>> meshes_;
    double time_ = 0.0;  // without a fluid solver
    long long frame_ = 0;  // frames advanced, without a fluid solver
    double deformMs_ = 0.0;
    double voxelizeMs_ = 0.0;
    long long recomputedCells_ = 0;
    bool keepSharpCoverage_ = true;
};

}  // namespace eikon::sim
