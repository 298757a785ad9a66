// Milliseconds per fluid substep at 64³ and 128³ (targets on 2 cores:
// 64³ < 60 ms, 128³ < 500 ms): a hot-plate plume in a 0.5 m box of air open
// at the top, warmed up for a few steps so the pressure solve has real work.
// Each iteration is one FluidSimulation::step at CFL ≈ 1; the counters report
// the per-phase times, the pressure PCG iterations and the relative residual
// reached (tolerance 1e-6), the diffusion iterations (Gauss–Seidel sweeps or
// CG iterations) summed over the fields, as FluidSimulation::lastTimings()
// logs them, and the CPU time of the whole process (all threads) per step,
// which other load on a shared machine does not inflate as it does the wall
// time.
#include "bench/ProcessCpuTime.h"
#include "sim/fluid/FluidSimulation.h"

#include <benchmark/benchmark.h>

#include <algorithm>

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

void BM_FluidStep(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    const eikon::GridSpec grid{glm::ivec3(n), glm::dvec3(0.0), glm::dvec3(0.5)};
    FluidSimulation sim(plumeScene(n), grid);
    const double h = 0.5 / n;
    auto dt = [&] { return std::min(0.02, h / std::max(sim.state().flow.maxCellCrossingRate() * h, 1e-6)); };
    for (int warm = 0; warm < 10; ++warm) sim.step(dt());
    double phaseMs[4] = {0, 0, 0, 0};
    double iterations = 0, diffusionIterations = 0, residual = 0;
    const double cpuStart = processCpuMs();
    for (auto _ : state) {
        sim.step(dt());
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
    state.counters["max_cfl"] = sim.state().flow.maxCellCrossingRate() * dt();
}

BENCHMARK(BM_FluidStep)->Arg(64)->Arg(128)->Unit(benchmark::kMillisecond)->Iterations(8);

}  // namespace

BENCHMARK_MAIN();
