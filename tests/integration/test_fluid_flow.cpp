// Whole-solver behaviour: buoyancy, projection, conservation, stability and
// the Taylor–Green viscous decay — on both backends, the CPU's and the GPU's
// (sim/gpu, on llvmpipe where there is no GPU), with the same tolerances.
#include "sim/fluid/FluidSimulation.h"

#include "sim/fluid/ParallelOps.h"
#include "sim/gpu/GpuFluidBackend.h"
#include "tests/integration/GlTestContext.h"
#include "tests/unit/FluidStiffRun.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace eikon::sim {
namespace {

enum class Backend { Cpu, Gpu };

// Runs the solver's substeps on `backend` from here on.
void place(FluidSimulation& sim, Backend backend) {
    if (backend == Backend::Cpu) return;
    test::glContext();
    sim.attachDevice(std::make_unique<gpu::GpuFluidBackend>(sim));
}

class FluidFlow : public ::testing::TestWithParam<Backend> {};

INSTANTIATE_TEST_SUITE_P(Backends, FluidFlow, ::testing::Values(Backend::Cpu, Backend::Gpu),
                         [](const ::testing::TestParamInfo<Backend>& backend) {
                             return backend.param == Backend::Cpu ? std::string("Cpu") : std::string("Gpu");
                         });

GridSpec box(int n, double size = 0.5) { return GridSpec{glm::ivec3(n), glm::dvec3(0.0), glm::dvec3(size)}; }

SimDesc airIn(int n) {
    SimDesc desc;
    desc.resolution = glm::ivec3(n);
    return desc;
}

double maxSpeed(const MacGrid& mac) {
    double m = 0.0;
    for (const GridField& u : mac.velocity) m = std::max(m, maxAbs(u.values));
    return m;
}

double maxDivergence(const FluidSimulation& sim) {
    const MacGrid& mac = sim.state().flow;
    double m = 0.0;
    const glm::ivec3 n = mac.grid.resolution;
    for (int k = 0; k < n.z; ++k)
        for (int j = 0; j < n.y; ++j)
            for (int i = 0; i < n.x; ++i)
                if (!sim.domain().isSolid(i, j, k)) m = std::max(m, std::abs(mac.divergence(i, j, k)));
    return m;
}

double kineticEnergy(const MacGrid& mac) {
    double e = 0.0;
    for (const GridField& u : mac.velocity) e += 0.5 * dot(u.values, u.values);
    return e * mac.grid.voxelVolume();
}

// Acceptance: a hot plate under still air in a closed 0.5 m box at 24³, with
// an obstacle in the plume: after every projection max|∇·u|·h / max|u| stays
// below 1e-4 (pressure tolerance 1e-6), and the plume rises above the plate.
TEST_P(FluidFlow, BuoyantPlumeIsDivergenceFreeAndRises) {
    SimDesc desc = airIn(24);
    SimDesc::Source plate;
    plate.region = {glm::dvec3(0.18, 0.0, 0.18), glm::dvec3(0.32, 0.03, 0.32)};
    plate.temperature = 373.15;
    desc.sources.push_back(plate);
    SimDesc::Obstacle ball;
    ball.kind = SimDesc::Obstacle::Kind::Sphere;
    ball.sphere = {glm::dvec3(0.35, 0.3, 0.25), 0.06};
    desc.obstacles.push_back(ball);
    desc.frameTime = 0.05;
    FluidSimulation sim(desc, box(24));
    place(sim, GetParam());
    const FluidSimulation& view = sim;  // reads the state without taking it back from a device
    for (int frame = 0; frame < 16; ++frame) {
        sim.advanceFrame();
        const double h = view.state().flow.h.x;
        EXPECT_LT(maxDivergence(view) * h / maxSpeed(view.state().flow), 1e-4) << "frame " << frame;
    }
    const GridField& v = view.state().flow.velocity[1];
    EXPECT_GT(v(12, 6, 12), 0.03) << "hot air above the plate should rise";
    EXPECT_GT(view.state().temperature(12, 3, 12), desc.ambientTemperature + 1.0);
}

// Syrup (concentration 1, 29% denser) released in the top half of a water
// tank sinks: its centre of mass falls.
TEST_P(FluidFlow, DenseLiquidSinks) {
    SimDesc desc = airIn(16);
    desc.fluid = SimDesc::Fluid::Liquid;
    desc.concentrationExpansion = 0.289;
    desc.viscosity = 1e-6;
    desc.concentrationDiffusivity = 0.0;
    desc.frameTime = 0.05;
    FluidSimulation sim(desc, box(16, 0.2));
    GridField& blob = sim.state().concentration;
    for (int k = 5; k < 11; ++k)
        for (int j = 10; j < 14; ++j)
            for (int i = 5; i < 11; ++i) blob(i, j, k) = 1.0;
    place(sim, GetParam());
    const FluidSimulation& view = sim;
    auto centreHeight = [&] {
        const GridField& c = view.state().concentration;
        double mass = 0.0, moment = 0.0;
        for (int k = 0; k < 16; ++k)
            for (int j = 0; j < 16; ++j)
                for (int i = 0; i < 16; ++i) {
                    mass += c(i, j, k);
                    moment += c(i, j, k) * j;
                }
        return moment / mass;
    };
    const double before = centreHeight();
    for (int frame = 0; frame < 4; ++frame) sim.advanceFrame();
    EXPECT_LT(centreHeight(), before - 1.0) << "the centre of mass should fall by more than a cell";
}

// Acceptance: closed box, no sources, a hot and a dense blob stirring the
// flow for 200 steps. Tolerances: the heat excess Σ(T − T_amb) and the mass
// Σc drift by less than 0.5%; no value leaves its initial range by more than 1e-6.
TEST_P(FluidFlow, ClosedBoxConservesScalarsWithinHalfAPercent) {
    const int n = 16;
    SimDesc desc = airIn(n);
    desc.concentrationExpansion = 0.05;
    desc.thermalDiffusivity = 1e-4;
    desc.concentrationDiffusivity = 1e-4;
    FluidSimulation sim(desc, box(n));
    FluidState& initial = sim.state();
    for (int k = 4; k < 9; ++k)
        for (int j = 2; j < 6; ++j)
            for (int i = 3; i < 8; ++i) initial.temperature(i, j, k) = desc.ambientTemperature + 30.0;
    for (int k = 7; k < 12; ++k)
        for (int j = 10; j < 14; ++j)
            for (int i = 8; i < 13; ++i) initial.concentration(i, j, k) = 1.0;
    place(sim, GetParam());
    const FluidSimulation& view = sim;
    auto heat = [&] {
        const GridField& t = view.state().temperature;
        return sum(t.values) - desc.ambientTemperature * t.count();
    };
    const double heat0 = heat();
    const double mass0 = sum(view.state().concentration.values);
    for (int step = 0; step < 200; ++step) sim.step(0.02);
    const FluidState& s = view.state();
    EXPECT_GT(maxSpeed(s.flow), 0.05) << "the blobs should have stirred the box";
    EXPECT_NEAR(heat() / heat0, 1.0, 0.005);
    EXPECT_NEAR(sum(s.concentration.values) / mass0, 1.0, 0.005);
    const auto [tLow, tHigh] = std::minmax_element(s.temperature.values.begin(), s.temperature.values.end());
    EXPECT_GE(*tLow, desc.ambientTemperature - 1e-6);
    EXPECT_LE(*tHigh, desc.ambientTemperature + 30.0 + 1e-6);
    const auto [cLow, cHigh] = std::minmax_element(s.concentration.values.begin(), s.concentration.values.end());
    EXPECT_GE(*cLow, -1e-6);
    EXPECT_LE(*cHigh, 1.0 + 1e-6);
}

// Acceptance: steps at CFL 10 with every diffusivity 100× the explicit limit
// Δt·D/h² = 1/6 run without NaN, and the kinetic energy never grows without
// forces (bound: 1.001 × the initial energy); temperature stays in its
// initial range. (The stability suite runs the same at CFL 20 and 10⁴×.)
TEST_P(FluidFlow, StableAtCfl10AndHundredTimesTheExplicitDiffusionLimit) {
    const StiffRunResult run =
        runStiffVortex(16, 10.0, 100.0, 20, [backend = GetParam()](FluidSimulation& sim) { place(sim, backend); });
    EXPECT_TRUE(run.finite);
    EXPECT_LE(run.maxEnergyRatio, 1.001);
    EXPECT_GE(run.minTemperature, run.ambientTemperature - 1e-6);
    EXPECT_LE(run.maxTemperature, run.ambientTemperature + run.hotExcess + 1e-6);
}

// Acceptance: the 2D Taylor–Green vortex u = U sin x cos y, v = −U cos x sin y
// on [0, π]² is an exact Navier–Stokes solution with free-slip walls whose
// kinetic energy decays as exp(−4νt). On 32 × 32 × 2 cells the measured rate
// matches 4ν within 5%.
TEST_P(FluidFlow, TaylorGreenVortexDecaysAtTheViscousRate) {
    const int n = 32;
    const double pi = std::numbers::pi;
    SimDesc desc;
    desc.resolution = glm::ivec3(n, n, 2);
    desc.gravity = glm::dvec3(0.0);
    desc.viscosity = 0.05;
    desc.thermalDiffusivity = desc.concentrationDiffusivity = 0.0;
    desc.pressureTolerance = 1e-8;
    const GridSpec grid{desc.resolution, glm::dvec3(0.0), glm::dvec3(pi, pi, pi / 16.0)};
    FluidSimulation sim(desc, grid);
    MacGrid& mac = sim.state().flow;
    const double amplitude = 0.1;
    for (int axis = 0; axis < 2; ++axis) {
        GridField& u = mac.velocity[axis];
        for (int k = 0; k < u.size.z; ++k)
            for (int j = 0; j < u.size.y; ++j)
                for (int i = 0; i < u.size.x; ++i) {
                    const glm::dvec3 p = mac.position(u, i, j, k);
                    u(i, j, k) = axis == 0 ? amplitude * std::sin(p.x) * std::cos(p.y)
                                           : -amplitude * std::sin(p.y) * std::cos(p.x);
                }
    }
    const double energy0 = kineticEnergy(mac);
    place(sim, GetParam());
    const double dt = 0.05;
    const int steps = 40;
    for (int step = 0; step < steps; ++step) sim.step(dt);
    const FluidSimulation& view = sim;
    const double rate = -std::log(kineticEnergy(view.state().flow) / energy0) / (steps * dt);
    RecordProperty("decay_rate_over_analytic", std::to_string(rate / (4.0 * desc.viscosity)));
    EXPECT_NEAR(rate / (4.0 * desc.viscosity), 1.0, 0.05);
}

}  // namespace
}  // namespace eikon::sim
