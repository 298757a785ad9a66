#include "sim/gpu/GpuFluidBackend.h"

#include "bridge/layout/GpuLayouts.h"
#include "gl/ShaderLibrary.h"
#include "sim/fluid/DiffusionRoles.h"
#include "sim/fluid/SolverLimits.h"
#include "sim/fluid/VorticityConfinement.h"
#include "sim/gpu/GpuDomain.h"

#include <glm/vec4.hpp>

#include <algorithm>
#include <utility>
#include <vector>

namespace eikon::sim::gpu {

namespace {

enum Phase { kSources, kAdvection, kDiffusion, kProjection };
const char* const kVelocityNames[3] = {"velocity_x", "velocity_y", "velocity_z"};

std::array<GpuField, 3> velocityFields(const MacGrid& mac) {
    std::array<GpuField, 3> fields;
    for (int axis = 0; axis < 3; ++axis)
        fields[axis] = GpuField(mac.velocity[axis], solverResource(kVelocityNames[axis], mac.velocity[axis].size));
    return fields;
}

void record(PhaseTiming& timing, const SolveStats& stats) {
    timing.iterations += stats.iterations;
    timing.residual = std::max(timing.residual, stats.relativeResidual);
}

}  // namespace

GpuFluidBackend::GpuFluidBackend(const FluidSimulation& simulation)
    : desc_(simulation.desc()),
      domain_(simulation.domain()),
      h_(simulation.state().flow.h),
      velocity_(velocityFields(simulation.state().flow)),
      temperature_(simulation.state().temperature, solverResource("temperature", domain_.cells),
                   desc_.ambientTemperature),
      concentration_(simulation.state().concentration, solverResource("concentration", domain_.cells)),
      dye_(simulation.state().dye, solverResource("dye", domain_.cells)),
      pressure_(simulation.state().pressure, solverResource("pressure", domain_.cells)),
      solid_(solidCellFlags(domain_)),
      openFaces_(openFaceBits(domain_)),
      sources_(simulation.sources(), simulation.state(), desc_.ambientTemperature),
      advection_(domain_.cells, h_),
      massCorrection_(temperature_.count()),
      pressureSolver_(domain_, h_),
      buoyancy_(gl::compileComputeProgram("sim/buoyancy.comp")),
      boundaries_(gl::compileComputeProgram("sim/velocity_boundaries.comp")) {
    if (desc_.vorticityConfinement > 0.0) {
        vorticity_ = gl::Buffer(temperature_.count() * sizeof(glm::vec4), solverResource("vorticity", domain_.cells));
        vorticityPass_ = gl::compileComputeProgram("sim/vorticity.comp");
        confinementPass_ = gl::compileComputeProgram("sim/vorticity_confinement.comp");
    }
    const DiffusionRoles roles = diffusionRoles(domain_, simulation.sources(), simulation.state().flow);
    temperatureDiffusion_ = GpuDiffusion(domain_.cells, roles.temperature);
    concentrationDiffusion_ = GpuDiffusion(domain_.cells, roles.scalars);
    dyeDiffusion_ = GpuDiffusion(domain_.cells, roles.scalars);
    for (int axis = 0; axis < 3; ++axis)
        velocityDiffusion_[axis] = GpuDiffusion(velocity_[axis].size(), roles.velocity[axis]);
    glGenQueries(static_cast<GLsizei>(timestamps_.size()), timestamps_.data());
}

GpuFluidBackend::~GpuFluidBackend() { glDeleteQueries(static_cast<GLsizei>(timestamps_.size()), timestamps_.data()); }

void GpuFluidBackend::upload(const FluidState& state) {
    for (int axis = 0; axis < 3; ++axis) velocity_[axis].upload(state.flow.velocity[axis]);
    temperature_.upload(state.temperature);
    concentration_.upload(state.concentration);
    dye_.upload(state.dye);
    pressure_.upload(state.pressure);
    pressureSolver_.setInitialGuess(pressure_);
    busBytes_ += fieldBytes();
}

void GpuFluidBackend::download(FluidState& state) {
    downloadScalars(state);
    for (int axis = 0; axis < 3; ++axis) velocity_[axis].download(state.flow.velocity[axis]);
    pressure_.download(state.pressure);
    busBytes_ += fieldBytes() - scalarBytes();
}

void GpuFluidBackend::downloadScalars(FluidState& state) {
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    temperature_.download(state.temperature);
    concentration_.download(state.concentration);
    dye_.download(state.dye);
    busBytes_ += scalarBytes();
}

std::uint64_t GpuFluidBackend::scalarBytes() const {
    return (temperature_.count() + concentration_.count() + dye_.count()) * sizeof(float);
}

std::uint64_t GpuFluidBackend::fieldBytes() const {
    std::uint64_t samples = pressure_.count();
    for (const GpuField& u : velocity_) samples += u.count();
    return samples * sizeof(float) + scalarBytes();
}

std::uint64_t GpuFluidBackend::takeBusBytes() { return std::exchange(busBytes_, 0); }

double GpuFluidBackend::maxCellCrossingRate() {
    double rate = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
        reduction_.run(GpuReduction::Operation::MaxAbs, GpuReduction::Element::Float, velocity_[axis].buffer(),
                       velocity_[axis].count(), axis);
    }
    for (int axis = 0; axis < 3; ++axis) rate = std::max(rate, reduction_.read(axis) / h_[axis]);
    busBytes_ += 3 * sizeof(double);
    return rate;
}

void GpuFluidBackend::enforceVelocityBoundaries() {
    boundaries_.use();
    solid_.bindStorage(layout::kSolverCells);
    glUniform3i(boundaries_.uniform("cells"), domain_.cells.x, domain_.cells.y, domain_.cells.z);
    glUniform1ui(boundaries_.uniform("open_faces"), openFaces_);
    for (int axis = 0; axis < 3; ++axis) {
        velocity_[axis].bind(layout::kSolverTarget);
        glUniform1i(boundaries_.uniform("axis"), axis);
        boundaries_.dispatchOverCells(velocity_[axis].size());
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void GpuFluidBackend::addBuoyancy(double dt) {
    buoyancy_.use();
    solid_.bindStorage(layout::kSolverCells);
    temperature_.bind(layout::kSolverSource);
    concentration_.bind(layout::kSolverField);
    glUniform3i(buoyancy_.uniform("cells"), domain_.cells.x, domain_.cells.y, domain_.cells.z);
    glUniform1ui(buoyancy_.uniform("open_faces"), openFaces_);
    glUniform1f(buoyancy_.uniform("thermal_expansion"), static_cast<float>(desc_.thermalExpansion));
    glUniform1f(buoyancy_.uniform("concentration_expansion"), static_cast<float>(desc_.concentrationExpansion));
    for (int axis = 0; axis < 3; ++axis) {
        if (desc_.gravity[axis] == 0.0) continue;
        velocity_[axis].bind(layout::kSolverTarget);
        glUniform1i(buoyancy_.uniform("axis"), axis);
        glUniform1f(buoyancy_.uniform("dt_times_g"), static_cast<float>(dt * desc_.gravity[axis]));
        buoyancy_.dispatchOverCells(velocity_[axis].size());
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void GpuFluidBackend::addVorticityConfinement(double dt) {
    if (desc_.vorticityConfinement == 0.0) return;
    const glm::vec3 h(h_);
    vorticityPass_.use();
    velocity_[0].bind(layout::kSolverVelocityX);
    velocity_[1].bind(layout::kSolverVelocityY);
    velocity_[2].bind(layout::kSolverVelocityZ);
    vorticity_.bindStorage(layout::kSolverVorticity);
    glUniform3i(vorticityPass_.uniform("cells"), domain_.cells.x, domain_.cells.y, domain_.cells.z);
    glUniform3f(vorticityPass_.uniform("h"), h.x, h.y, h.z);
    vorticityPass_.dispatchOverCells(domain_.cells);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    confinementPass_.use();
    solid_.bindStorage(layout::kSolverCells);
    vorticity_.bindStorage(layout::kSolverVorticity);
    glUniform3i(confinementPass_.uniform("cells"), domain_.cells.x, domain_.cells.y, domain_.cells.z);
    glUniform1ui(confinementPass_.uniform("open_faces"), openFaces_);
    glUniform3f(confinementPass_.uniform("h"), h.x, h.y, h.z);
    glUniform1f(confinementPass_.uniform("scale"),
                static_cast<float>(desc_.vorticityConfinement * confinementLength(h_)));
    glUniform1f(confinementPass_.uniform("dt"), static_cast<float>(dt));
    glUniform1f(confinementPass_.uniform("min_gradient"), static_cast<float>(kMinVorticityGradient));
    for (int axis = 0; axis < 3; ++axis) {
        velocity_[axis].bind(layout::kSolverTarget);
        glUniform1i(confinementPass_.uniform("axis"), axis);
        confinementPass_.dispatchOverCells(velocity_[axis].size());
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void GpuFluidBackend::checkScalars(const SolverPhase& when) {
    finite_.check(temperature_, "temperature", "cell", when);
    finite_.check(concentration_, "concentration", "cell", when);
    finite_.check(dye_, "dye", "cell", when);
}

void GpuFluidBackend::checkVelocity(const SolverPhase& when) {
    for (int axis = 0; axis < 3; ++axis) finite_.check(velocity_[axis], kVelocityNames[axis], "face", when);
}

void GpuFluidBackend::substep(double dt, std::vector<PhaseTiming>& timings) {
    finite_.begin();
    // What was handed in from outside; scalars first, as on the CPU.
    checkScalars(kSubstepStart);
    checkVelocity(kSubstepStart);
    finite_.check(pressure_, "pressure", "cell", kSubstepStart);
    glQueryCounter(timestamps_[0], GL_TIMESTAMP);

    sources_.applyScalars(temperature_, concentration_, dye_);
    addBuoyancy(dt);
    addVorticityConfinement(dt);
    sources_.applyVelocity(velocity_);
    enforceVelocityBoundaries();
    checkScalars(kAfterSources);
    checkVelocity(kAfterSources);
    glQueryCounter(timestamps_[1], GL_TIMESTAMP);

    const std::vector<GpuField*> scalars{&temperature_, &concentration_, &dye_};
    if (domain_.anyOpenFace()) {
        advection_.advect(velocity_, scalars, dt);
    } else {
        massCorrection_.recordBudgets(scalars);
        advection_.advect(velocity_, scalars, dt);
        massCorrection_.restore(scalars);
    }
    enforceVelocityBoundaries();
    sources_.applyScalars(temperature_, concentration_, dye_);
    checkScalars(kAfterAdvection);
    checkVelocity(kAfterAdvection);
    glQueryCounter(timestamps_[2], GL_TIMESTAMP);

    PhaseTiming& diffusion = timings[kDiffusion];
    auto run = [&](GpuDiffusion& solver, GpuField& field, double diffusivity) {
        record(diffusion, solver.diffuse(field, h_, dt * diffusivity, kDiffusionTolerance, kMaxSolverIterations));
        busBytes_ += solver.bytesReadBack();
    };
    for (int axis = 0; axis < 3; ++axis) run(velocityDiffusion_[axis], velocity_[axis], desc_.viscosity);
    run(temperatureDiffusion_, temperature_, desc_.thermalDiffusivity);
    run(concentrationDiffusion_, concentration_, desc_.concentrationDiffusivity);
    run(dyeDiffusion_, dye_, desc_.dyeDiffusivity);
    checkScalars(kAfterDiffusion);
    checkVelocity(kAfterDiffusion);
    glQueryCounter(timestamps_[3], GL_TIMESTAMP);

    sources_.applyVelocity(velocity_);
    record(timings[kProjection],
           pressureSolver_.project(velocity_, pressure_, desc_.pressureTolerance, kMaxSolverIterations));
    busBytes_ += pressureSolver_.bytesReadBack();
    checkVelocity(kAfterProjection);
    finite_.check(pressure_, "pressure", "cell", kAfterProjection);
    glQueryCounter(timestamps_[4], GL_TIMESTAMP);

    finite_.finish();
    busBytes_ += finite_.bytesRead();
    std::array<GLuint64, 5> ns{};
    for (std::size_t q = 0; q < ns.size(); ++q) glGetQueryObjectui64v(timestamps_[q], GL_QUERY_RESULT, &ns[q]);
    for (int phase = kSources; phase <= kProjection; ++phase)
        timings[phase].milliseconds += 1e-6 * static_cast<double>(ns[phase + 1] - ns[phase]);
}

}  // namespace eikon::sim::gpu
