// The grid passes on each device (render.device, render/stages/StageDevice.h),
// per cell of a graded N³ field (a hot-air bump beside a glass-like
// interface, κ in a slab): the prepare stage (Gaussian smoothing, 9³ window,
// and gradient) and the step structure (min/max pyramid and labels, with
// the reference labels), each timed to completion with glFinish — the
// native stages' reads of their input textures and uploads of their
// outputs included — and the native kernels alone (smoothing, gradient,
// pyramid, labels). Counters per cell of the grid: ns_per_cell (wall time)
// and cpu_ns_per_cell (the process's CPU time, every thread — llvmpipe's
// and TBB's — included: the work done, which a shared machine's load does
// not change).
#include "bench/ProcessCpuTime.h"
#include "bridge/grid/FieldSet.h"
#include "gl/GlContext.h"
#include "render/stages/FieldTextures.h"
#include "render/stages/GaussianKernel.h"
#include "render/stages/NativePrepare.h"
#include "render/stages/NativeStepStructure.h"
#include "render/stages/PrepareStage.h"
#include "render/stages/StepStructureStage.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <vector>

namespace {

using namespace eikon;

FieldSet gradedCube(int n) {
    FieldSet fields;
    fields.grid = GridSpec{glm::ivec3(n), glm::dvec3(-0.5), glm::dvec3(0.5)};
    fields.deltaIndex.resize(fields.grid.cellCount());
    fields.extinction.assign(3 * fields.grid.cellCount(), 0.0f);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const glm::dvec3 x = fields.grid.cellCentre(i, j, k);
                const std::size_t cell = fields.grid.linearIndex(i, j, k);
                const glm::dvec3 a = x - glm::dvec3(-0.2, 0.1, 0.0);
                double delta = -1.2e-4 * std::exp(-glm::dot(a, a) / 0.01);
                if (x.z > 0.3) delta += 0.25 * (1.0 + std::tanh((x.x - 0.3) / (2.0 / n)));
                fields.deltaIndex[cell] = static_cast<float>(delta);
                if (x.y < -0.3)
                    for (std::size_t c = 0; c < 3; ++c) fields.extinction[3 * cell + c] = static_cast<float>(-0.3 - x.y);
            }
    fields.indexVersion = fields.extinctionVersion = 1;
    return fields;
}

gl::GlContext& context() {
    static std::unique_ptr<gl::GlContext> headless = gl::createHeadlessContext();
    headless->makeCurrent();
    return *headless;
}

render::StageDevice deviceOf(const benchmark::State& state) {
    return state.range(1) ? render::StageDevice::Cpu : render::StageDevice::Gpu;
}

template <typename Work>
void timeEach(benchmark::State& state, std::size_t cells, Work&& work) {
    work();  // once untimed: the first run allocates and touches its arrays
    glFinish();
    double seconds = 0.0, cpuMs = 0.0;
    for (auto _ : state) {
        const double cpuStart = bench::processCpuMs();
        const auto start = std::chrono::steady_clock::now();
        work();
        glFinish();
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        state.SetIterationTime(elapsed);
        seconds += elapsed;
        cpuMs += bench::processCpuMs() - cpuStart;
    }
    state.counters["ns_per_cell"] = 1e9 * seconds / double(state.iterations()) / double(cells);
    state.counters["cpu_ns_per_cell"] = 1e6 * cpuMs / double(state.iterations()) / double(cells);
}

void BM_PrepareStage(benchmark::State& state) {
    context();
    const FieldSet fields = gradedCube(static_cast<int>(state.range(0)));
    render::FieldTextures textures;
    textures.upload(render::hostUpload(fields));
    render::PrepareStage prepare(GridDesc{fields.grid.resolution, fields.grid.boundsMin, fields.grid.boundsMax},
                                 textures, deviceOf(state));
    timeEach(state, fields.grid.cellCount(), [&] { prepare.run(textures); });
}

void BM_StepStructureStage(benchmark::State& state) {
    context();
    const FieldSet fields = gradedCube(static_cast<int>(state.range(0)));
    render::FieldTextures textures;
    textures.upload(render::hostUpload(fields));
    render::StepStructureStage steps(fields.grid, TracerDesc{}, true, false, deviceOf(state));
    steps.enableReference(0.5 * fields.grid.smallestVoxelEdge());
    timeEach(state, fields.grid.cellCount(), [&] { steps.run(textures.index(), textures); });
}

// The native kernels alone, on host arrays (no texture reads or uploads).
void BM_NativeKernels(benchmark::State& state) {
    const FieldSet fields = gradedCube(static_cast<int>(state.range(0)));
    const glm::ivec3 r = fields.grid.resolution;
    const std::vector<float> weights = render::gaussianHalfKernel(1.5);
    std::vector<float> index = fields.deltaIndex, scratch;
    std::vector<glm::vec4> gradient, pyramid, labels;
    std::vector<glm::vec4> kappa(fields.grid.cellCount());
    for (std::size_t cell = 0; cell < kappa.size(); ++cell)
        kappa[cell] = {fields.extinction[3 * cell], fields.extinction[3 * cell + 1], fields.extinction[3 * cell + 2], 0.0f};
    const shader::OctreeLabelRule rule{0.002f, 0.002f, 1.0f, 0.06f, 0.004f, 0.014f, 0.01f};
    const int kernel = static_cast<int>(state.range(1));
    if (kernel == 3) render::octreePyramidNative({index.data(), kappa.data(), nullptr}, r, pyramid);
    timeEach(state, fields.grid.cellCount(), [&] {
        if (kernel == 0)
            render::smoothIndexNative(index, r, weights, scratch);  // in place, again each time
        else if (kernel == 1)
            render::indexGradientNative(index, r, glm::vec3(fields.grid.voxelSize()), gradient);
        else if (kernel == 2)
            render::octreePyramidNative({index.data(), kappa.data(), nullptr}, r, pyramid);
        else
            render::octreeLabelsNative(pyramid, r, rule, labels);
    });
    static const char* const kNames[] = {"smoothing (3 passes)", "gradient", "pyramid", "labels"};
    state.SetLabel(kNames[kernel]);
}

}  // namespace

// Arguments: cells per edge, device (0: compute shaders, 1: native loops).
BENCHMARK(BM_PrepareStage)->ArgsProduct({{64, 128}, {0, 1}})->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StepStructureStage)->ArgsProduct({{64, 128}, {0, 1}})->UseManualTime()->Unit(benchmark::kMillisecond);
// Arguments: cells per edge, kernel (0 smoothing, 1 gradient, 2 pyramid, 3 labels).
BENCHMARK(BM_NativeKernels)->ArgsProduct({{128}, {0, 1, 2, 3}})->UseManualTime()->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
