// `eikon bench`: photon-tracer throughput on a scene at a given size —
// steps/s, voxel deposits/s, ms per relight, and a bare march kernel (no
// deposits, attenuation or receivers) as the limit the tracer is held to —
// the view pass of camera-only frames, and each stage's time per unit of
// its work beside its count (BenchKernels.h).
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace eikon::app {

struct BenchOptions {
    std::string scenePath = "scenes/default.json";
    int resolution = 128;
    long long photons = 1 << 20;
    int repeats = 5;
    std::vector<std::string> overrides;
    std::string outFile;  // optional JSON summary
};

void addBenchCommand(CLI::App& app, BenchOptions& options);
int benchCommand(const BenchOptions& options);

}  // namespace eikon::app
