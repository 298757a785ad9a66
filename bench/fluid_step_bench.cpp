// Milliseconds per fluid substep at 64³, 128³ and 256³ on each backend
// (targets on 2 cores: 64³ < 60 ms, 128³ < 500 ms on the CPU; on an H100/H200
// 128³ ≤ 5 ms on the GPU): a hot-plate plume in a 0.5 m box of air open at
// the top, warmed up for a few steps so the pressure solve has real work.
// BM_FluidStep/cpu runs the TBB backend, BM_FluidStep/gpu the OpenGL compute
// backend (sim/gpu) on the headless context — llvmpipe where there is no GPU.
// A GPU step returns once its NaN checks are read back, so the wall time
// covers the whole step. Each iteration is one FluidSimulation::step at a
// CFL number near 1 fixed after the warm-up; the counters report
// the per-phase times, the pressure PCG iterations and the relative residual
// reached (tolerance 1e-6), the diffusion iterations (Gauss–Seidel sweeps or
// CG iterations) summed over the fields, as FluidSimulation::lastTimings()
// logs them, and the CPU time of the whole process (all threads) per step,
// which other load on a shared machine does not inflate as it does the wall
// time.
#include "bench/ProcessCpuTime.h"
#include "gl/GlContext.h"
#include "sim/fluid/FluidSimulation.h"
#include "sim/gpu/GpuFluidBackend.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <memory>

namespace {

using eikon::bench::processCpuMs;
using eikon::sim::FluidSimulation;

eikon::SimDesc plumeScene(int n) {
    eikon::SimDesc desc;
    desc.resolution = glm::ivec3(n);
    eikon::SimDesc::Source plate;
    plate.region = {glm::dvec3(0.15, 0.0, 0.15), glm::dvec3(0.35, 0.02, 0.35)};
    plate.temperature = 373.15;
    desc.sources.push_back(plate);
    desc.boundaries[3] = eikon::SimDesc::Boundary::Open;  // open top, as over a stove
    return desc;
}

enum Backend { kCpu, kGpu };

void BM_FluidStep(benchmark::State& state, Backend backend) {
    static std::unique_ptr<eikon::gl::GlContext> context;  // one for the process, made on first use
    const int n = static_cast<int>(state.range(0));
    const eikon::GridSpec grid{glm::ivec3(n), glm::dvec3(0.0), glm::dvec3(0.5)};
    FluidSimulation sim(plumeScene(n), grid);
    if (backend == kGpu) {
        if (!context) context = eikon::gl::createHeadlessContext();
        sim.attachDevice(std::make_unique<eikon::sim::gpu::GpuFluidBackend>(sim));
        state.SetLabel(context->info().renderer);
    }
    const FluidSimulation& view = sim;  // reads the state without taking it back from a device
    const double h = 0.5 / n;
    auto cflOneStep = [&] { return std::min(0.02, h / std::max(view.state().flow.maxCellCrossingRate() * h, 1e-6)); };
    for (int warm = 0; warm < 10; ++warm) sim.step(cflOneStep());
    const double dt = cflOneStep();
    double phaseMs[4] = {0, 0, 0, 0};
    double iterations = 0, diffusionIterations = 0, residual = 0;
    const double cpuStart = processCpuMs();
    for (auto _ : state) {
        sim.step(dt);
        const auto& timings = sim.lastTimings();
        for (int p = 0; p < 4; ++p) phaseMs[p] += timings[p].milliseconds;
        iterations += timings[3].iterations;
        diffusionIterations += timings[2].iterations;
        residual = std::max(residual, timings[3].residual);
    }
    const double steps = static_cast<double>(state.iterations());
    state.counters["sources_ms"] = phaseMs[0] / steps;
    state.counters["advection_ms"] = phaseMs[1] / steps;
    state.counters["diffusion_ms"] = phaseMs[2] / steps;
    state.counters["projection_ms"] = phaseMs[3] / steps;
    state.counters["pressure_iters"] = iterations / steps;
    state.counters["diffusion_iters"] = diffusionIterations / steps;
    state.counters["max_residual"] = residual;
    state.counters["process_cpu_ms"] = (processCpuMs() - cpuStart) / steps;
    state.counters["max_cfl"] = view.state().flow.maxCellCrossingRate() * dt;
}

BENCHMARK_CAPTURE(BM_FluidStep, cpu, kCpu)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond)->Iterations(8);
BENCHMARK_CAPTURE(BM_FluidStep, cpu, kCpu)->Arg(256)->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK_CAPTURE(BM_FluidStep, gpu, kGpu)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond)->Iterations(8);
BENCHMARK_CAPTURE(BM_FluidStep, gpu, kGpu)->Arg(256)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace

BENCHMARK_MAIN();
