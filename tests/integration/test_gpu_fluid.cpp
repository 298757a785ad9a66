// The fluid solver's GPU backend (sim/gpu/GpuFluidBackend.h) against its
// CPU backend: the same plume stepped on both, the same NaN/Inf reports,
// the same phase records, and what crosses the bus.
#include "sim/fluid/FluidSimulation.h"

#include "bridge/core/Error.h"
#include "sim/gpu/GpuFiniteCheck.h"
#include "sim/gpu/GpuFluidBackend.h"
#include "sim/gpu/GpuOpticalMapping.h"
#include "sim/optics/OpticalMapping.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

namespace eikon::sim {
namespace {

// The hot-plate plume's solver (scenes/hot_plate_plume.json: air over a
// 450 K plate, open top, frame 0.04 s in 2 substeps) at `cells`³ over a 0.4 m box.
SimDesc shimmerPlume(int cells) {
    SimDesc desc;
    desc.resolution = glm::ivec3(cells);
    desc.bounds = BoxShape{glm::dvec3(-0.2, 0.0, -0.2), glm::dvec3(0.2, 0.4, 0.2)};
    desc.boundaries[faceIndex(1, 1)] = SimDesc::Boundary::Open;
    SimDesc::Source plate;
    plate.region = {glm::dvec3(-0.08, 0.0, -0.08), glm::dvec3(0.08, 0.012, 0.08)};
    plate.temperature = 450.0;
    desc.sources.push_back(plate);
    return desc;
}

const GridSpec kRenderGrid{glm::ivec3(16), glm::dvec3(-0.2, 0.0, -0.2), glm::dvec3(0.2, 0.4, 0.2)};

void placeOnGpu(FluidSimulation& sim) {
    test::glContext();
    sim.attachDevice(std::make_unique<gpu::GpuFluidBackend>(sim));
}

// ‖a − b‖₂ / ‖b − reference‖₂ over the samples of one field.
double relativeL2(const GridField& a, const GridField& b, double reference = 0.0) {
    double difference = 0.0, norm = 0.0;
    for (std::size_t s = 0; s < a.count(); ++s) {
        difference += (a.values[s] - b.values[s]) * (a.values[s] - b.values[s]);
        norm += (b.values[s] - reference) * (b.values[s] - reference);
    }
    return std::sqrt(difference / norm);
}

// Acceptance: the plume after 50 substeps at 32³ on both backends. The
// temperature is compared as its excess over ambient (relative to T itself
// every difference would look 10⁴× smaller), the velocity over all faces.
// Bound 1e-3; float32 storage alone rounds each sample by 6e-8 relative, and
// what separates the runs further is the solvers' tolerances (pressure 1e-6,
// each iteration's float32 rounding of the fields).
TEST(GpuFluid, PlumeMatchesTheCpuBackendAfterFiftySteps) {
    const SimDesc desc = shimmerPlume(32);
    FluidSimulation cpu(desc, kRenderGrid);
    FluidSimulation gpu(desc, kRenderGrid);
    placeOnGpu(gpu);
    EXPECT_EQ(gpu.deviceName(), "gpu");
    for (int step = 0; step < 50; ++step) {
        cpu.step(0.02);
        gpu.step(0.02);
    }
    const FluidState& a = static_cast<const FluidSimulation&>(gpu).state();
    const FluidState& b = static_cast<const FluidSimulation&>(cpu).state();
    const double temperature = relativeL2(a.temperature, b.temperature, desc.ambientTemperature);
    double velocityDifference = 0.0, velocityNorm = 0.0;
    for (int axis = 0; axis < 3; ++axis)
        for (std::size_t s = 0; s < a.flow.velocity[axis].count(); ++s) {
            const double d = a.flow.velocity[axis].values[s] - b.flow.velocity[axis].values[s];
            velocityDifference += d * d;
            velocityNorm += b.flow.velocity[axis].values[s] * b.flow.velocity[axis].values[s];
        }
    const double velocity = std::sqrt(velocityDifference / velocityNorm);
    test::reportFigure("plume_temperature_relative_l2", temperature);
    test::reportFigure("plume_velocity_relative_l2", velocity);
    EXPECT_LT(temperature, 1e-3);
    EXPECT_LT(velocity, 1e-3);
    EXPECT_GT(std::sqrt(velocityNorm / 3.0), 0.0) << "the plate should have set the air moving";
}

// Relative L2 of the face velocities of a against b, over all three axes.
double velocityRelativeL2(const FluidState& a, const FluidState& b) {
    double difference = 0.0, norm = 0.0;
    for (int axis = 0; axis < 3; ++axis)
        for (std::size_t s = 0; s < a.flow.velocity[axis].count(); ++s) {
            const double d = a.flow.velocity[axis].values[s] - b.flow.velocity[axis].values[s];
            difference += d * d;
            norm += b.flow.velocity[axis].values[s] * b.flow.velocity[axis].values[s];
        }
    return std::sqrt(difference / norm);
}

// Vorticity confinement (sim.vorticity_confinement, [Fedkiw01] eq. 11) runs
// alike on both backends: the plume with ε = 2 after 30 substeps at 24³
// agrees to 1e-3 as above, while confinement itself moves the flow by far
// more than that (the bound would fail if either backend skipped it).
TEST(GpuFluid, VorticityConfinementMatchesTheCpuBackend) {
    SimDesc desc = shimmerPlume(24);
    desc.vorticityConfinement = 2.0;
    FluidSimulation cpu(desc, kRenderGrid);
    FluidSimulation gpu(desc, kRenderGrid);
    FluidSimulation plain(shimmerPlume(24), kRenderGrid);
    placeOnGpu(gpu);
    for (int step = 0; step < 30; ++step) {
        cpu.step(0.02);
        gpu.step(0.02);
        plain.step(0.02);
    }
    const FluidState& a = static_cast<const FluidSimulation&>(gpu).state();
    const FluidState& b = static_cast<const FluidSimulation&>(cpu).state();
    const FluidState& c = static_cast<const FluidSimulation&>(plain).state();
    const double parity = velocityRelativeL2(a, b);
    const double effect = velocityRelativeL2(c, b);
    test::reportFigure("confinement_velocity_relative_l2", parity);
    test::reportFigure("confinement_effect_relative_l2", effect);
    EXPECT_LT(parity, 1e-3);
    EXPECT_LT(relativeL2(a.temperature, b.temperature, desc.ambientTemperature), 1e-3);
    EXPECT_GT(effect, 1e-2);
}

// The phases are recorded alike: same names, iterations of the same order.
TEST(GpuFluid, PhaseRecordsMatchTheCpuBackend) {
    const SimDesc desc = shimmerPlume(24);
    FluidSimulation cpu(desc, kRenderGrid);
    FluidSimulation gpu(desc, kRenderGrid);
    placeOnGpu(gpu);
    for (int step = 0; step < 5; ++step) {
        cpu.step(0.02);
        gpu.step(0.02);
    }
    ASSERT_EQ(gpu.lastTimings().size(), cpu.lastTimings().size());
    for (std::size_t p = 0; p < cpu.lastTimings().size(); ++p) {
        const PhaseTiming& g = gpu.lastTimings()[p];
        const PhaseTiming& c = cpu.lastTimings()[p];
        EXPECT_EQ(g.phase, c.phase);
        EXPECT_GT(g.milliseconds, 0.0) << g.phase;
        EXPECT_NEAR(g.iterations, c.iterations, 0.5 * c.iterations + 3) << g.phase;
        EXPECT_LE(g.residual, 1e-5) << g.phase;
    }
    EXPECT_GT(gpu.lastTimings()[3].iterations, 0) << "the projection iterates";
}

std::string messageOf(FluidSimulation& sim) {
    try {
        sim.step(0.01);
    } catch (const NumericalBreakdown& error) {
        return error.what();
    }
    return "no error";
}

// NaN/Inf on the GPU is reported as the CPU reports it: field, sample and
// phase — values handed in at the start of a substep, and a buoyancy that
// overflows after sources.
TEST(GpuFluid, NonFiniteValuesAreCaughtWithFieldAndCell) {
    SimDesc desc;
    desc.resolution = glm::ivec3(12);
    desc.bounds = BoxShape{glm::dvec3(-0.2, 0.0, -0.2), glm::dvec3(0.2, 0.4, 0.2)};
    {
        FluidSimulation sim(desc, kRenderGrid);
        placeOnGpu(sim);
        sim.state().temperature(3, 4, 5) = std::numeric_limits<double>::quiet_NaN();
        EXPECT_EQ(messageOf(sim),
                  "sim (the solver's temperature at cell (3, 4, 5) of sim.resolution, at the start of a substep): expected a "
                  "finite value, found nan");
    }
    {
        FluidSimulation sim(desc, kRenderGrid);
        placeOnGpu(sim);
        sim.state().flow.velocity[1](2, 7, 1) = std::numeric_limits<double>::infinity();
        EXPECT_EQ(messageOf(sim),
                  "sim (the solver's velocity_y at face (2, 7, 1) of sim.resolution, at the start of a substep): expected a "
                  "finite value, found inf");
    }
    {
        SimDesc hot = desc;
        hot.thermalExpansion = 1e30;  // overflows float32 at the one hot cell
        FluidSimulation sim(hot, kRenderGrid);
        placeOnGpu(sim);
        sim.state().temperature(1, 2, 3) += 1e10;
        EXPECT_EQ(messageOf(sim), "sim.sources, sim.thermal_expansion, sim.concentration_expansion, sim.gravity, "
                                  "sim.vorticity_confinement (the solver's velocity_y at face (1, 2, 3) of "
                                  "sim.resolution, after sources): expected a finite value, found inf");
    }
}

// A one-dimensional pass over more entries than 65 535 work groups of 256
// hold (a 256³ grid has 16.8 million samples) reaches the last of them: a
// NaN there is found and named.
TEST(GpuFluid, PassesReachEntriesPastOneAxisOfWorkGroups) {
    test::glContext();
    GridField field(glm::ivec3(4097, 4096, 1), glm::dvec3(0.5), 1.0);
    field(4096, 4095, 0) = std::numeric_limits<double>::quiet_NaN();
    const gpu::GpuField onGpu(field, gpu::solverResource("dye", field.size));
    gpu::GpuFiniteCheck check;
    check.begin();
    check.check(onGpu, "dye", "cell", SolverPhase{"after a test", "sim"});
    try {
        check.finish();
        ADD_FAILURE() << "the NaN in the last sample was not found";
    } catch (const NumericalBreakdown& error) {
        EXPECT_EQ(std::string(error.what()),
                  "sim (the solver's dye at cell (4096, 4095, 0) of sim.resolution, after a test): expected a finite "
                  "value, found nan");
    }
}

// The largest |a − b| over max |b|, for float fields.
double relativeMaxDifference(const std::vector<float>& a, const std::vector<float>& b) {
    double difference = 0.0, largest = 0.0;
    for (std::size_t s = 0; s < a.size(); ++s) {
        difference = std::max(difference, std::abs(static_cast<double>(a[s]) - b[s]));
        largest = std::max(largest, std::abs(static_cast<double>(b[s])));
    }
    return difference / largest;
}

// The optical mapping on the GPU against OpticalMapping.cpp on the same
// scalars: a render grid finer than the solver's and reaching past its box
// (cells outside see the ambient fluid), air by Gladstone–Dale and a liquid
// by Lorentz–Lorenz mixing with a dye that absorbs and scatters. Bound 1e-6
// of the largest value: both form the index in float64 and round δn, κ, σs
// to float32 once; the GPU's trilinear weights come from float32 scalars.
TEST(GpuFluid, OpticalMappingMatchesTheCpus) {
    test::glContext();
    SimDesc liquid;
    liquid.fluid = SimDesc::Fluid::Liquid;
    liquid.mixing = SimDesc::Mixing::LorentzLorenz;
    liquid.dyeExtinction = Rgb{3.0, 2.0, 1.0};
    liquid.dyeScattering = Rgb{1.0, 0.5, 0.25};
    for (const SimDesc& base : {SimDesc{}, liquid}) {
        SimDesc desc = base;
        desc.resolution = glm::ivec3(10, 14, 8);
        desc.bounds = BoxShape{glm::dvec3(-0.2, 0.0, -0.2), glm::dvec3(0.2, 0.4, 0.2)};
        const GridSpec renderGrid{glm::ivec3(21, 17, 19), glm::dvec3(-0.25, -0.05, -0.25), glm::dvec3(0.25, 0.45, 0.25)};
        FluidSimulation sim(desc, renderGrid);
        FluidState& state = sim.state();
        for (int k = 0; k < 8; ++k)
            for (int j = 0; j < 14; ++j)
                for (int i = 0; i < 10; ++i) {
                    state.temperature(i, j, k) = desc.ambientTemperature + 40.0 * std::sin(0.5 * i + 0.3 * j) * std::cos(0.7 * k);
                    state.concentration(i, j, k) = 0.5 + 0.5 * std::sin(0.4 * i - 0.6 * j + 0.2 * k);
                    state.dye(i, j, k) = 1.0 + std::cos(0.3 * i + 0.2 * j - 0.5 * k);
                }
        const OpticalModel model(desc);
        FieldSet cpu;
        cpu.grid = renderGrid;
        cpu.referenceIndex = base.fluid == SimDesc::Fluid::Liquid ? 1.333 : 1.0;
        cpu.deltaIndex.resize(renderGrid.cellCount());
        cpu.extinction.resize(model.absorbs() ? 3 * renderGrid.cellCount() : 0);
        cpu.scattering.resize(model.scatters() ? 3 * renderGrid.cellCount() : 0);
        mapOpticalFields(model, sim.scalars(), viewsOf(cpu));

        const gpu::GpuField temperature(state.temperature, gpu::solverResource("temperature", desc.resolution),
                                        desc.ambientTemperature);
        const gpu::GpuField concentration(state.concentration, gpu::solverResource("concentration", desc.resolution));
        const gpu::GpuField dye(state.dye, gpu::solverResource("dye", desc.resolution));
        auto target = [](std::size_t floats) {
            return floats ? gl::Buffer(floats * sizeof(float), gl::GpuResource{}) : gl::Buffer();
        };
        const gl::Buffer deltaIndex = target(cpu.deltaIndex.size());
        const gl::Buffer extinction = target(cpu.extinction.size());
        const gl::Buffer scattering = target(cpu.scattering.size());
        const gpu::GpuOpticalMapping mapping(desc, sim.solverGrid(), renderGrid, cpu.referenceIndex);
        mapping.map(temperature, concentration, dye, {deltaIndex.id(), extinction.id(), scattering.id()});
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        const double index = relativeMaxDifference(deltaIndex.downloadAll<float>(), cpu.deltaIndex);
        test::reportFigure(base.fluid == SimDesc::Fluid::Liquid ? "liquid_delta_index" : "air_delta_index", index);
        EXPECT_LT(index, 1e-6);
        if (model.absorbs()) {
            const double kappa = relativeMaxDifference(extinction.downloadAll<float>(), cpu.extinction);
            const double sigma = relativeMaxDifference(scattering.downloadAll<float>(), cpu.scattering);
            test::reportFigure("dye_extinction", kappa);
            test::reportFigure("dye_scattering", sigma);
            EXPECT_LT(kappa, 1e-6);
            EXPECT_LT(sigma, 1e-6);
        }
    }
}

// After the first frame's upload, a frame moves only what the host decides
// on: the CFL count's three largest speeds, the stopping tests' residuals
// and the NaN checks' slots — a few kilobytes, not a field.
TEST(GpuFluid, FramesMoveNoFieldAcrossTheBus) {
    SimDesc desc = shimmerPlume(24);
    FluidSimulation sim(desc, kRenderGrid);
    placeOnGpu(sim);
    sim.advanceFrame();
    sim.takeBusBytes();  // the first upload
    sim.advanceFrame();
    const std::uint64_t bytes = sim.takeBusBytes();
    test::reportFigure("bus_bytes_per_frame", static_cast<double>(bytes));
    EXPECT_GT(bytes, 0u);
    EXPECT_LT(bytes, 24u * 24u * 24u * sizeof(float)) << "less than one field";
}

}  // namespace
}  // namespace eikon::sim
