// Milliseconds per file of a volume sequence: what `eikon run` spends
// checking each later file before frame 0 (sim/volume/VolumeSequence.h,
// checkVolumeFrames: header, grid table and every grid's tree, type,
// metadata and transform, no value sampled) against what loading the file
// for its frame costs (the same, then every grid read and sampled onto the
// render grid), and the header alone (the file read, its header and grid
// table checked, OpenVDB's descriptors read). The file is a Blender-like
// smoke frame: a 96×192×96 domain holding a noisy plume as density,
// temperature, flame (float, saved as half) and velocity (vec3s), blosc
// compressed with active masks, as Mantaflow writes them; sampled onto a
// 128³ render grid. Each iteration reads the file anew (from the page
// cache). Not run by ctest.
#include "io/vdb/VdbVolumeFile.h"

#include <benchmark/benchmark.h>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>

namespace {

namespace fs = std::filesystem;
using eikon::GridSpec;
using eikon::io::VdbVolumeFile;

constexpr int kDomain = 96;  // cells across; twice as many up

const fs::path& smokeFile() {
    static const fs::path path = [] {
        openvdb::initialize();
        auto density = openvdb::FloatGrid::create(0.0f), temperature = openvdb::FloatGrid::create(0.0f),
             flame = openvdb::FloatGrid::create(0.0f);
        auto velocity = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.0f));
        density->setName("density");
        temperature->setName("temperature");
        flame->setName("flame");
        velocity->setName("velocity");
        auto d = density->getAccessor(), t = temperature->getAccessor(), f = flame->getAccessor();
        auto v = velocity->getAccessor();
        std::mt19937 rng(1);
        std::uniform_real_distribution<float> noise(-1.0f, 1.0f);
        for (int k = 0; k < kDomain; ++k)  // a cone widening upward from the floor's centre
            for (int j = 0; j < 2 * kDomain; ++j)
                for (int i = 0; i < kDomain; ++i) {
                    const double x = (i - 0.5 * kDomain) / kDomain, z = (k - 0.5 * kDomain) / kDomain;
                    const double y = j / (2.0 * kDomain), r = std::hypot(x, z), radius = 0.08 + 0.35 * y;
                    if (r > radius) continue;
                    const auto w = static_cast<float>((1.0 - r / radius) * (1.0 - y));
                    const openvdb::Coord c(i, j, k);
                    d.setValue(c, w * (1.0f + 0.3f * noise(rng)));
                    t.setValue(c, 2.0f * w * (1.0f + 0.1f * noise(rng)));
                    if (y < 0.2) f.setValue(c, w * (1.0f + 0.2f * noise(rng)));
                    v.setValue(c, openvdb::Vec3s(0.1f * noise(rng), w * (1.0f + 0.2f * noise(rng)), 0.1f * noise(rng)));
                }
        openvdb::GridPtrVec grids{density, temperature, flame, velocity};
        for (auto& grid : grids) {
            grid->setTransform(openvdb::math::Transform::createLinearTransform(1.0 / kDomain));
            grid->setSaveFloatAsHalf(true);
        }
        const fs::path file = fs::temp_directory_path() / "eikon_vdb_check_bench.vdb";
        openvdb::io::File out(file.string());
        out.setCompression(openvdb::io::COMPRESS_BLOSC | openvdb::io::COMPRESS_ACTIVE_MASK);
        out.write(grids);
        return file;
    }();
    return path;
}

const GridSpec kRenderGrid{glm::ivec3(128), glm::dvec3(0.0, 0.0, 0.0), glm::dvec3(1.0, 2.0, 1.0)};
const glm::dmat4 kPlacement(1.0);

void reportFile(benchmark::State& state) { state.counters["file_MB"] = static_cast<double>(fs::file_size(smokeFile())) / 1e6; }

void BM_HeaderOnly(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(VdbVolumeFile(smokeFile()).gridNames());
    reportFile(state);
}

void BM_CheckBeforeFrameZero(benchmark::State& state) {
    for (auto _ : state) {
        const VdbVolumeFile file(smokeFile());
        for (const char* grid : {"density", "temperature", "flame"}) file.check(grid, 1, kRenderGrid, kPlacement);
        file.check("velocity", 3, kRenderGrid, kPlacement);
    }
    reportFile(state);
}

void BM_LoadForItsFrame(benchmark::State& state) {
    for (auto _ : state) {
        const VdbVolumeFile file(smokeFile());
        for (const char* grid : {"density", "temperature", "flame"})
            benchmark::DoNotOptimize(file.sample(grid, 1, kRenderGrid, kPlacement));
        benchmark::DoNotOptimize(file.sample("velocity", 3, kRenderGrid, kPlacement));
    }
    reportFile(state);
}

BENCHMARK(BM_HeaderOnly)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CheckBeforeFrameZero)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LoadForItsFrame)->Unit(benchmark::kMillisecond)->Iterations(5);

}  // namespace

BENCHMARK_MAIN();
