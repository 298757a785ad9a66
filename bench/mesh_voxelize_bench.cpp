// Milliseconds to deform and voxelize a 20k-triangle mesh into 128³ per
// frame (issue 6 target on 2 cores: < 60 ms with band-limited updates).
// The subject is a sphere of 20 160 triangles, radius 0.35 m in a 1 m box.
//   BM_LocalDeformation: a bump of radius 0.15 m on one side pulses from frame
//     to frame, so only the band around it is recomputed.
//   BM_GlobalDeformation: every vertex moves (the whole sphere breathes), so
//     the whole surface band is recomputed — the worst case.
//   BM_TwistDeformer, BM_ArapDeformer: the scene's deformers on the same mesh
//     (a twist about y growing each frame; ARAP with the south cap held and
//     the north cap lifted and turned, 8 iterations per frame).
// Counters: triangles, recomputed cells per frame, triangles whose distance
// was computed per frame (the sub-mesh near the recomputed cells), the mean
// wall ms per frame in the deformer, in the unsigned distance (choosing the
// sub-mesh, OpenVDB's meshToVolume), in its sign (row parity of the whole
// mesh) and in the coverage of the recomputed cells, and the process CPU ms
// per frame (all threads).
#include "bench/ProcessCpuTime.h"
#include "sim/deform/ArapDeformer.h"
#include "sim/deform/MeshShapes.h"
#include "sim/deform/SpatialDeformers.h"
#include "sim/voxelize/MeshCoverage.h"

#include <benchmark/benchmark.h>

#include <glm/geometric.hpp>

#include <chrono>
#include <cmath>

namespace {

using namespace eikon;
using bench::processCpuMs;

const GridSpec kGrid{glm::ivec3(128), glm::dvec3(-0.5), glm::dvec3(0.5)};

TriangleMesh subject() { return sim::sphereMesh(glm::dvec3(0.0), 0.35, 71, 144); }

void runFrames(benchmark::State& state, bool local) {
    const TriangleMesh rest = subject();
    TriangleMesh mesh = rest;
    sim::MeshCoverage coverage(kGrid);
    coverage.update(mesh);
    const glm::dvec3 bumpCentre(0.35, 0.0, 0.0);
    int frame = 0;
    long long cells = 0;
    double distanceTriangles = 0.0, distanceMs = 0.0, signMs = 0.0, coverageMs = 0.0;
    const double cpuStart = processCpuMs();
    for (auto _ : state) {
        const double amplitude = 0.02 * std::sin(0.7 * ++frame);
        for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
            const glm::dvec3 p = rest.vertices[v];
            const double d2 = glm::dot(p - bumpCentre, p - bumpCentre) / (0.08 * 0.08);
            const double weight = local ? (d2 < 9.0 ? std::exp(-d2) : 0.0) : 1.0;  // cut at 3σ: the rest stays put
            mesh.vertices[v] = p * (1.0 + amplitude * weight / 0.35);
        }
        coverage.update(mesh);
        cells += coverage.lastRecomputedCells();
        distanceTriangles += static_cast<double>(coverage.lastDistanceTriangles());
        distanceMs += coverage.lastDistanceMilliseconds();
        signMs += coverage.lastSignMilliseconds();
        coverageMs += coverage.lastCoverageMilliseconds();
    }
    state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
    const double frames = static_cast<double>(state.iterations());
    state.counters["cells_per_frame"] = static_cast<double>(cells) / frames;
    state.counters["distance_triangles"] = distanceTriangles / frames;
    state.counters["distance_ms"] = distanceMs / frames;
    state.counters["sign_ms"] = signMs / frames;
    state.counters["coverage_ms"] = coverageMs / frames;
    state.counters["process_cpu_ms"] = (processCpuMs() - cpuStart) / frames;
}

void runDeformer(benchmark::State& state, sim::Deformer& deformer, TriangleMesh& mesh) {
    sim::MeshCoverage coverage(kGrid);
    coverage.update(mesh);
    double time = 0.0, deformMs = 0.0, distanceMs = 0.0, signMs = 0.0, coverageMs = 0.0;
    const double cpuStart = processCpuMs();
    for (auto _ : state) {
        time += 0.04;
        const auto start = std::chrono::steady_clock::now();
        deformer.deform(time, mesh.vertices);
        deformMs += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        coverage.update(mesh);
        distanceMs += coverage.lastDistanceMilliseconds();
        signMs += coverage.lastSignMilliseconds();
        coverageMs += coverage.lastCoverageMilliseconds();
    }
    const double frames = static_cast<double>(state.iterations());
    state.counters["triangles"] = static_cast<double>(mesh.triangles.size());
    state.counters["deform_ms"] = deformMs / frames;
    state.counters["distance_ms"] = distanceMs / frames;
    state.counters["sign_ms"] = signMs / frames;
    state.counters["coverage_ms"] = coverageMs / frames;
    state.counters["process_cpu_ms"] = (processCpuMs() - cpuStart) / frames;
}

void BM_TwistDeformer(benchmark::State& state) {
    TriangleMesh mesh = subject();
    DeformerDesc desc;
    desc.kind = DeformerDesc::Kind::Twist;
    desc.amount = {{0.0, 0.0}, {100.0, 10000.0}};  // 100°/m more every second
    sim::TwistDeformer twist(desc, mesh);
    runDeformer(state, twist, mesh);
}

void BM_ArapDeformer(benchmark::State& state) {
    TriangleMesh mesh = subject();
    DeformerDesc desc;
    desc.kind = DeformerDesc::Kind::Arap;
    desc.handles.push_back({glm::dvec3(-1, -1, -1), glm::dvec3(1, -0.3, 1), {}});
    desc.handles.push_back({glm::dvec3(-1, 0.3, -1), glm::dvec3(1, 1, 1),
                            {{0.0, {}}, {10.0, {glm::dvec3(0, 0.5, 0), glm::dvec3(0, 0, 300), 1.0}}}});
    sim::ArapDeformer arap(desc, mesh, "bench");
    runDeformer(state, arap, mesh);
}

void BM_LocalDeformation(benchmark::State& state) { runFrames(state, true); }
void BM_GlobalDeformation(benchmark::State& state) { runFrames(state, false); }

BENCHMARK(BM_LocalDeformation)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_GlobalDeformation)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_TwistDeformer)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ArapDeformer)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
