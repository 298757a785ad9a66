// The multiple-scattering lattice (render/stages/LatticeScattering) per
// converged frame: a cube of N³ cells entirely filled with a homogeneous
// medium of optical depth 8 across, lit over its whole top face by a
// collimated beam (its scattered power the lattice's source, exact per
// cell), at albedo 0.5, 0.9 and 0.99, on 6, 14 and 18 links, from a cold start
// at the default tolerance (1e-3). Counters: steps per channel to converge,
// ms per step, and the ledger's closure. The medium is grey, so one channel
// is solved (LatticeStats::grey). [Bernabei12]'s Table I: 70–86 ms per frame
// at 128³ on a GTX 465.
#include "bridge/grid/FieldSet.h"
#include "gl/GlContext.h"
#include "gl/GlObjects.h"
#include "render/stages/FieldTextures.h"
#include "render/stages/LatticeScattering.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <vector>

namespace {

using namespace eikon;

struct FilledCube {
    FieldSet fields;
    std::vector<float> source;  // W per cell, RGB
};

FilledCube filledCube(int n, double albedo) {
    const double depth = 8.0, side = 1.0;  // τ across, m
    FilledCube cube;
    cube.fields.grid = {glm::ivec3(n), glm::dvec3(0.0), glm::dvec3(side)};
    const std::size_t cells = cube.fields.grid.cellCount();
    const double sigmaT = depth / side, h = side / n, dtau = sigmaT * h;
    cube.fields.deltaIndex.assign(cells, 0.0f);
    cube.fields.extinction.assign(3 * cells, static_cast<float>(sigmaT));
    cube.fields.scattering.assign(3 * cells, static_cast<float>(albedo * sigmaT));
    cube.source.assign(3 * cells, 0.0f);
    for (int k = 0; k < n; ++k) {
        // The beam enters at z = side and runs down: E0 = 1 W/m² over each cell's h².
        const int fromTop = n - 1 - k;
        const float scattered =
            static_cast<float>(albedo * h * h * (std::exp(-fromTop * dtau) - std::exp(-(fromTop + 1) * dtau)));
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                for (int c = 0; c < 3; ++c) cube.source[3 * cube.fields.grid.linearIndex(i, j, k) + c] = scattered;
    }
    return cube;
}

gl::GlContext& context() {
    static std::unique_ptr<gl::GlContext> headless = gl::createHeadlessContext();
    headless->makeCurrent();
    return *headless;
}

void BM_LatticeFrame(benchmark::State& state) {
    context();
    const int n = static_cast<int>(state.range(0));
    const double albedo = static_cast<double>(state.range(1)) / 100.0;
    render::LatticeSettings settings;
    settings.directions = static_cast<int>(state.range(2));
    const FilledCube cube = filledCube(n, albedo);
    render::FieldTextures textures;
    textures.upload(render::hostUpload(cube.fields));
    const gl::Buffer source(cube.source.size() * sizeof(float), cube.source.data());
    render::LatticeScattering lattice(cube.fields.grid, textures, settings);
    render::LatticeStats stats;
    double seconds = 0.0;
    for (auto _ : state) {
        lattice.restart();
        const auto start = std::chrono::steady_clock::now();
        stats = lattice.run(textures, source);
        glFinish();
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        state.SetIterationTime(elapsed);
        seconds += elapsed;
    }
    const double frames = static_cast<double>(state.iterations());
    state.counters["steps"] = stats.channels[0].iterations;
    state.counters["ms_per_step"] = 1e3 * seconds / frames / std::max(1, stats.iterations());
    state.counters["balance_error"] = stats.balanceError();
    state.counters["grey"] = stats.grey ? 1 : 0;
    state.counters["capped"] = stats.capped() ? 1 : 0;
}

void latticeCases(benchmark::internal::Benchmark* bench) {
    for (int n : {64, 128})
        for (int albedo : {50, 90, 99})
            for (int directions : {6, 14, 18}) bench->Args({n, albedo, directions});
}

BENCHMARK(BM_LatticeFrame)->Apply(latticeCases)->ArgNames({"n", "albedo_pct", "links"})->UseManualTime()
    ->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
