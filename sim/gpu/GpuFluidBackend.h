// The fluid solver's substep as OpenGL 4.5 compute passes: the phases,
// stopping rules and checks of FluidSimulation.h on GPU buffers — sources
// and buoyancy (GpuSources, buoyancy.comp), vorticity confinement
// (vorticity.comp, vorticity_confinement.comp), MacCormack advection with the
// closed box's totals restored (GpuAdvection, GpuMassCorrection), implicit
// diffusion (GpuDiffusion) and the multigrid-preconditioned pressure
// projection (GpuPressureSolver). Fields are float32 (the temperature as
// T − T_amb); linear solves iterate in float64 to the CPU's tolerances.
// Needs a current OpenGL context, on the thread that calls it.
#pragma once

#include "sim/fluid/FluidDevice.h"
#include "sim/fluid/FluidSimulation.h"
#include "sim/gpu/GpuAdvection.h"
#include "sim/gpu/GpuDiffusion.h"
#include "sim/gpu/GpuField.h"
#include "sim/gpu/GpuFiniteCheck.h"
#include "sim/gpu/GpuMassCorrection.h"
#include "sim/gpu/GpuPressureSolver.h"
#include "sim/gpu/GpuReduction.h"
#include "sim/gpu/GpuSources.h"

#include <array>
#include <memory>

namespace eikon::sim::gpu {

class GpuFluidBackend final : public FluidDevice {
public:
    // The solver description, domain and sources of `simulation`, whose
    // state attachDevice then uploads.
    explicit GpuFluidBackend(const FluidSimulation& simulation);
    ~GpuFluidBackend() override;

    std::string name() const override { return "gpu"; }
    void upload(const FluidState& state) override;
    void download(FluidState& state) override;
    void downloadScalars(FluidState& state) override;
    double maxCellCrossingRate() override;
    void substep(double dt, std::vector<PhaseTiming>& timings) override;
    std::uint64_t takeBusBytes() override;

    // The current scalars where they live, for the optical mapping on the GPU
    // (GpuOpticalMapping); the temperature as T − T_amb.
    const GpuField& temperature() const { return temperature_; }
    const GpuField& concentration() const { return concentration_; }
    const GpuField& dye() const { return dye_; }

private:
    void addBuoyancy(double dt);
    void addVorticityConfinement(double dt);
    void enforceVelocityBoundaries();
    void checkScalars(const SolverPhase& when);
    void checkVelocity(const SolverPhase& when);
    std::uint64_t fieldBytes() const;  // of every field: one upload or download
    std::uint64_t scalarBytes() const;  // of temperature, concentration and dye

    SimDesc desc_;
    FluidDomain domain_;
    glm::dvec3 h_;
    std::array<GpuField, 3> velocity_;
    GpuField temperature_, concentration_, dye_, pressure_;
    gl::Buffer solid_;  // uint per cell, for fluid_domain.glsl
    GLuint openFaces_ = 0;
    GpuSources sources_;
    GpuAdvection advection_;
    GpuMassCorrection massCorrection_;
    std::array<GpuDiffusion, 3> velocityDiffusion_;
    GpuDiffusion temperatureDiffusion_, concentrationDiffusion_, dyeDiffusion_;
    GpuPressureSolver pressureSolver_;
    GpuReduction reduction_;  // the CFL number's largest face speeds
    GpuFiniteCheck finite_;
    gl::Buffer vorticity_;  // vec4 (ω, |ω|) per cell; empty without confinement
    gl::Program buoyancy_, boundaries_, vorticityPass_, confinementPass_;
    std::array<GLuint, 5> timestamps_{};  // GL timer queries at the phase boundaries
    std::uint64_t busBytes_ = 0;
};

}  // namespace eikon::sim::gpu
