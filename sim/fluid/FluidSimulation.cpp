#include "sim/fluid/FluidSimulation.h"

#include "bridge/core/Error.h"
#include "sim/fluid/DiffusionRoles.h"
#include "sim/fluid/FiniteCheck.h"
#include "sim/fluid/MassCorrection.h"
#include "sim/fluid/ParallelOps.h"
#include "sim/fluid/SolverLimits.h"
#include "sim/fluid/VorticityConfinement.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace eikon::sim {

namespace {

enum Phase { kSources, kAdvection, kDiffusion, kProjection };

GridSpec solverGridOf(const SimDesc& desc, const GridSpec& renderGrid) {
    GridSpec grid{desc.resolution, renderGrid.boundsMin, renderGrid.boundsMax};
    if (desc.bounds) {
        grid.boundsMin = desc.bounds->min;
        grid.boundsMax = desc.bounds->max;
    }
    return grid;
}

FluidDomain domainOf(const SimDesc& desc, const MacGrid& mac) {
    FluidDomain domain(desc.resolution, desc.boundaries);
    addObstacles(domain, mac, desc.obstacles);
    return domain;
}

// Times a phase into a PhaseTiming.
class PhaseClock {
public:
    explicit PhaseClock(PhaseTiming& timing) : timing_(timing), start_(std::chrono::steady_clock::now()) {}
    ~PhaseClock() {
        timing_.milliseconds +=
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
    }
    PhaseClock(const PhaseClock&) = delete;
    PhaseClock& operator=(const PhaseClock&) = delete;

private:
    PhaseTiming& timing_;
    std::chrono::steady_clock::time_point start_;
};

void record(PhaseTiming& timing, const SolveStats& stats) {
    timing.iterations += stats.iterations;
    timing.residual = std::max(timing.residual, stats.relativeResidual);
}

}  // namespace

FluidSimulation::FluidSimulation(const SimDesc& desc, const GridSpec& renderGrid)
    : desc_(desc),
      state_(solverGridOf(desc, renderGrid), desc.ambientTemperature),
      domain_(domainOf(desc, state_.flow)),
      sources_(desc_, state_.flow, domain_),
      pressure_(std::make_unique<PressureSolver>(domain_, state_.flow.h)) {
    rebuildRoles();
    sources_.applyScalars(state_);
    timings_ = {{"sources"}, {"advection"}, {"diffusion"}, {"projection"}};
}

void FluidSimulation::rebuildRoles() {
    const DiffusionRoles roles = diffusionRoles(domain_, sources_, state_.flow);
    const glm::ivec3 cells = state_.flow.grid.resolution;
    temperatureDiffusion_ = ImplicitDiffusion(cells, roles.temperature);
    concentrationDiffusion_ = ImplicitDiffusion(cells, roles.scalars);
    dyeDiffusion_ = ImplicitDiffusion(cells, roles.scalars);
    for (int axis = 0; axis < 3; ++axis)
        velocityDiffusion_[axis] = ImplicitDiffusion(state_.flow.velocity[axis].size, roles.velocity[axis]);
}

void FluidSimulation::addSolidMask(const std::vector<std::uint8_t>& solid) {
    EIKON_CHECK_EQ(solid.size(), domain_.solid.size());
    EIKON_CHECK_MSG(!device_, "solids are added before a device takes the solver");
    for (std::size_t c = 0; c < solid.size(); ++c)
        if (solid[c]) domain_.solid[c] = 1;
    pressure_ = std::make_unique<PressureSolver>(domain_, state_.flow.h);
    rebuildRoles();
    enforceVelocityBoundaries(state_.flow, domain_);
}

void FluidSimulation::attachDevice(std::unique_ptr<FluidDevice> device) {
    device_ = std::move(device);
    device_->upload(state_);
    deviceAhead_ = hostAhead_ = false;
}

FluidState& FluidSimulation::state() {
    static_cast<const FluidSimulation&>(*this).state();
    if (device_) hostAhead_ = true;
    return state_;
}

const FluidState& FluidSimulation::state() const {
    if (deviceAhead_) {
        device_->download(const_cast<FluidState&>(state_));
        deviceAhead_ = false;
        hostScalarsCurrent_ = true;
    }
    return state_;
}

double FluidSimulation::maxCellCrossingRate() {
    if (!device_ || hostAhead_) return state_.flow.maxCellCrossingRate();
    return device_->maxCellCrossingRate();
}

void FluidSimulation::advanceFrame() {
    for (PhaseTiming& t : timings_) t = {t.phase};
    report_ = {};
    report_.budgetsKept = !device_;
    const std::array<double, 3> start = report_.budgetsKept ? scalarTotals() : std::array<double, 3>{};
    double remaining = desc_.frameTime;
    int minimumLeft = desc_.substeps;
    double rate = maxCellCrossingRate();
    while (true) {
        // Substeps left: at least the requested count, and enough that the
        // fastest face crosses at most `cfl` cells in one — refused before
        // the frame's count would pass max_substeps (a stiff flow would
        // otherwise run on for hours).
        const double needed = std::ceil(remaining * rate / desc_.cfl);
        if (report_.substeps + std::max(needed, static_cast<double>(minimumLeft)) > desc_.maxSubsteps)
            refuseSubsteps(frames_ + 1, report_.substeps + needed, rate, desc_);
        const int left = std::max(minimumLeft, static_cast<int>(needed));
        const double dt = left <= 1 ? remaining : remaining / left;
        substep(dt);
        ++report_.substeps;
        rate = maxCellCrossingRate();
        report_.cellsPerSubstep = std::max(report_.cellsPerSubstep, rate * dt);
        if (left <= 1) break;
        remaining -= dt;
        minimumLeft = std::max(minimumLeft - 1, 1);
    }
    report_.fastFlow = describeFastFlow(report_, desc_);
    if (report_.budgetsKept) closeBudgets(start);
    ++frames_;
    updateTime();
}

// Frames × frame time in one rounding (a sum of substeps drifts: 0.19999999999999998 s after five frames of 0.04 s),
// plus free steps.
void FluidSimulation::updateTime() { time_ = static_cast<double>(frames_) * desc_.frameTime + steppedTime_; }

void FluidSimulation::step(double dt) {
    for (PhaseTiming& t : timings_) t = {t.phase};
    report_ = {};  // a step is no frame: its count alone, no crossing read back, no budgets
    substep(dt);
    report_.substeps = 1;
    steppedTime_ += dt;
    updateTime();
}

void FluidSimulation::substep(double dt) {
    if (!device_) {
        substepOnCpu(dt);
        return;
    }
    if (hostAhead_) {
        device_->upload(state_);
        hostAhead_ = false;
    }
    device_->substep(dt, timings_);
    deviceAhead_ = true;
    hostScalarsCurrent_ = false;
}

void FluidSimulation::substepOnCpu(double dt) {
    checkFinite(kSubstepStart, kScalars | kVelocity | kPressure);  // what was handed in from outside
    {
        PhaseClock clock(timing(kSources));
        addToSources(sources_.applyScalars(state_));
        addBuoyancy(state_, domain_, desc_, dt);
        addVorticityConfinement(state_, domain_, desc_.vorticityConfinement, dt);
        sources_.applyVelocity(state_);
        enforceVelocityBoundaries(state_.flow, domain_);
        checkFinite(kAfterSources, kScalars | kVelocity);
    }
    {
        PhaseClock clock(timing(kAdvection));
        const std::vector<GridField*> scalars{&state_.temperature, &state_.concentration, &state_.dye};
        if (domain_.anyOpenFace()) {
            advect(state_.flow, scalars, dt, advection_);
        } else {
            advectConserving(scalars, dt);
        }
        enforceVelocityBoundaries(state_.flow, domain_);
        addToSources(sources_.applyScalars(state_));
        checkFinite(kAfterAdvection, kScalars | kVelocity);
    }
    {
        PhaseClock clock(timing(kDiffusion));
        const glm::dvec3 h = state_.flow.h;
        auto run = [&](ImplicitDiffusion& diffusion, GridField& field, double diffusivity) {
            record(timing(kDiffusion),
                   diffusion.diffuse(field, h, dt * diffusivity, kDiffusionTolerance, kMaxSolverIterations));
        };
        for (int axis = 0; axis < 3; ++axis)
            run(velocityDiffusion_[axis], state_.flow.velocity[axis], desc_.viscosity);
        // Heat conducted out of hot plates: the one change of a total here
        // (Neumann edges, solids excluded; Diffusion.h).
        const bool conducts = report_.budgetsKept && sources_.holdsTemperature();
        const double heatBefore = conducts ? sum(state_.temperature.values) : 0.0;
        run(temperatureDiffusion_, state_.temperature, desc_.thermalDiffusivity);
        if (conducts) addToSources({sum(state_.temperature.values) - heatBefore, 0.0, 0.0});
        run(concentrationDiffusion_, state_.concentration, desc_.concentrationDiffusivity);
        run(dyeDiffusion_, state_.dye, desc_.dyeDiffusivity);
        checkFinite(kAfterDiffusion, kScalars | kVelocity);
    }
    {
        PhaseClock clock(timing(kProjection));
        sources_.applyVelocity(state_);
        record(timing(kProjection),
               pressure_->project(state_.flow, state_.pressure, desc_.pressureTolerance, kMaxSolverIterations));
        checkFinite(kAfterProjection, kVelocity | kPressure);
    }
}

void FluidSimulation::advectConserving(const std::vector<GridField*>& scalars, double dt) {
    struct Budget {
        double total, low, high;
    };
    std::vector<Budget> budgets;
    for (const GridField* field : scalars) {
        const auto [low, high] = std::minmax_element(field->values.begin(), field->values.end());
        budgets.push_back({sum(field->values), *low, *high});
    }
    advect(state_.flow, scalars, dt, advection_);
    for (std::size_t f = 0; f < scalars.size(); ++f)
        restoreTotal(*scalars[f], budgets[f].total, budgets[f].low, budgets[f].high);
}

std::array<double, 3> FluidSimulation::scalarTotals() const {
    const double volume = state_.flow.grid.voxelVolume();
    const double cells = static_cast<double>(state_.temperature.count());
    return {(sum(state_.temperature.values) - cells * desc_.ambientTemperature) * volume,
            sum(state_.concentration.values) * volume, sum(state_.dye.values) * volume};
}

void FluidSimulation::addToSources(const std::array<double, 3>& change) {
    const double volume = state_.flow.grid.voxelVolume();
    report_.heat.sources += change[0] * volume;
    report_.concentration.sources += change[1] * volume;
    report_.dye.sources += change[2] * volume;
}

void FluidSimulation::closeBudgets(const std::array<double, 3>& start) {
    const std::array<double, 3> end = scalarTotals();
    ScalarBudget* const budgets[3] = {&report_.heat, &report_.concentration, &report_.dye};
    for (std::size_t s = 0; s < 3; ++s) {
        budgets[s]->total = end[s];
        budgets[s]->advection = end[s] - start[s] - budgets[s]->sources;
    }
}

void FluidSimulation::checkFinite(const SolverPhase& phase, unsigned fields) const {
    // Scalars first: buoyancy carries a bad temperature into the velocity.
    if (fields & kScalars) {
        requireFinite(state_.temperature, "temperature", "cell", phase);
        requireFinite(state_.concentration, "concentration", "cell", phase);
        requireFinite(state_.dye, "dye", "cell", phase);
    }
    if (fields & kVelocity) {
        const char* const axes[3] = {"velocity_x", "velocity_y", "velocity_z"};
        for (int axis = 0; axis < 3; ++axis) requireFinite(state_.flow.velocity[axis], axes[axis], "face", phase);
    }
    if (fields & kPressure) requireFinite(state_.pressure, "pressure", "cell", phase);
}

const FluidState& FluidSimulation::scalarState() const {
    scalars();
    return state_;
}

SolverScalars FluidSimulation::scalars() const {
    if (!hostScalarsCurrent_) {
        device_->downloadScalars(const_cast<FluidState&>(state_));
        hostScalarsCurrent_ = true;
    }
    return {solverGrid(), state_.temperature, state_.concentration, state_.dye, desc_.ambientTemperature};
}

}  // namespace eikon::sim
