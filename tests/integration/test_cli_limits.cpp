// What `eikon run` says where a scene goes past what eikon can compute or
// hold: a multiple-scattering lattice whose voxels are too thick for its
// float arithmetic (render/stages/LatticeScattering.h, the depth limit) or
// coarser than its validated resolution (a quarter of a reduced mean free
// path per voxel), and
// documented sizes that need more memory than the machine's limit
// (bridge/core/MemoryLimit.h, render/graph/MemoryEstimate.h), lowered here
// by EIKON_MEMORY_LIMIT_MB: refused before the big allocation.
#include "tests/integration/CliRun.h"
#include "tests/unit/VdbTestFiles.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using eikon::test::Outcome;
using eikon::test::readReport;
using eikon::test::runEikon;

class CliLimits : public eikon::test::CliFolderTest {
protected:
    CliLimits() : CliFolderTest("eikon_cli_limits_") {}
};

int count(const std::string& text, const std::string& what) {
    int found = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++found;
    return found;
}

// A medium of albedo 1 on 16³ voxels of 1/16 m, lit from above, its light
// diffused on the lattice: `extinction` 640/m is an optical depth of 40 per
// voxel, far past the limit of 14 on 14 links; 32/m is 2, within it but
// eight times the validated resolution; 3.2/m is 0.2, within both.
std::string albedoOneScene(double extinction) {
    const std::string sigma = std::to_string(extinction);
    return R"({
  "grid": {"resolution": [16, 16, 16], "bounds": {"min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5]}},
  "medium": {"index": 1.0, "extinction": [)" + sigma + ", " + sigma + ", " + sigma + R"(],
             "scattering": [)" + sigma + ", " + sigma + ", " + sigma + R"(]},
  "lights": [{"type": "point", "position": [0, 1.5, 0], "power": [10, 10, 10]}],
  "camera": {"position": [0, 0.5, 3], "target": [0, 0.5, 0], "up": [0, 1, 0], "fov_deg": 45},
  "render": {"photons": 4096, "width": 16, "height": 12, "seed": 3, "error_estimate": false},
  "tracer": {"multiple_scattering": "lbm"}
})";
}

// Beyond the depth limit the lattice's state stops moving at once (its
// change reads 0 and its ledger balances, all the light counted absorbed):
// the report says it is not converged and why, and stderr says so once a
// run, with the depth found, the limit and what to change (and, once, that
// the voxels are coarser than the validated resolution).
TEST_F(CliLimits, LatticeBeyondItsDepthLimitIsWarnedAndNotConverged) {
    const std::string thick = writeScene("thick.json", albedoOneScene(640.0));
    const Outcome outcome = runEikon("run " + thick + " --out " + (dir_ / "thick").string() + " --frames 2 --quiet");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    EXPECT_EQ(count(outcome.output, "eikon: warning:"), 2) << outcome.output;
    EXPECT_EQ(count(outcome.output, "too thick for the multiple-scattering lattice"), 1) << outcome.output;
    EXPECT_NE(outcome.output.find("optical depth up to 40 across a voxel, beyond its limit of 14"), std::string::npos)
        << outcome.output;
    EXPECT_NE(outcome.output.find("grid.resolution"), std::string::npos) << outcome.output;
    const std::vector<nlohmann::json> lines = readReport(dir_ / "thick" / "report.jsonl");
    ASSERT_EQ(lines.size(), 2u);
    ASSERT_TRUE(lines[0].contains("multiple_scattering"));
    for (const nlohmann::json& line : lines) {
        if (!line.contains("multiple_scattering")) continue;  // a still scene diffuses its light once
        const nlohmann::json& lattice = line.at("multiple_scattering");
        EXPECT_FALSE(lattice.at("converged").get<bool>()) << lattice;
        EXPECT_FALSE(lattice.at("capped").get<bool>()) << lattice;
        const nlohmann::json& depth = lattice.at("depth_limit");
        EXPECT_EQ(depth.at("voxels_beyond").get<int>(), 16 * 16 * 16) << depth;
        EXPECT_NEAR(depth.at("deepest_beyond").get<double>(), 40.0, 1e-3) << depth;
        EXPECT_NEAR(depth.at("optical_depth_per_voxel").get<double>(), 13.96, 0.01) << depth;
        EXPECT_NE(depth.at("warning").get<std::string>().find("grid.resolution"), std::string::npos) << depth;
    }

    const std::string thin = writeScene("thin.json", albedoOneScene(32.0));
    const Outcome within = runEikon("run " + thin + " --out " + (dir_ / "thin").string() + " --quiet");
    ASSERT_EQ(within.exitCode, 0) << within.output;
    EXPECT_EQ(count(within.output, "too thick"), 0) << within.output;
    const nlohmann::json lattice = readReport(dir_ / "thin" / "report.jsonl").at(0).at("multiple_scattering");
    EXPECT_TRUE(lattice.at("converged").get<bool>()) << lattice;
    EXPECT_EQ(lattice.at("depth_limit").at("voxels_beyond").get<int>(), 0) << lattice;
    EXPECT_FALSE(lattice.at("depth_limit").contains("warning")) << lattice;
}

// Voxels of reduced optical depth 2 (albedo 1, g = 0: σt′ = σt), eight
// times the validated quarter: stderr warns once, naming the depth, the
// limit and grid.resolution; the report's multiple_scattering and its
// per-frame error estimate carry the same. At 0.2 neither says anything.
TEST_F(CliLimits, LatticeCoarserThanItsValidatedResolutionIsWarned) {
    const std::string coarse = writeScene("coarse.json", albedoOneScene(32.0));
    const Outcome outcome = runEikon("run " + coarse + " --out " + (dir_ / "coarse").string() +
                                     " --frames 2 --quiet --set render.error_estimate=true");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    EXPECT_EQ(count(outcome.output, "coarser than the multiple-scattering lattice's validated resolution"), 1)
        << outcome.output;
    EXPECT_NE(outcome.output.find("up to 2 reduced mean free paths"), std::string::npos) << outcome.output;
    EXPECT_NE(outcome.output.find("beyond 0.25"), std::string::npos) << outcome.output;
    const nlohmann::json line = readReport(dir_ / "coarse" / "report.jsonl").at(0);
    const nlohmann::json& resolution = line.at("multiple_scattering").at("voxel_resolution");
    EXPECT_EQ(resolution.at("coarse_voxels").get<int>(), 16 * 16 * 16) << resolution;
    EXPECT_NEAR(resolution.at("coarsest_reduced_depth").get<double>(), 2.0, 1e-5) << resolution;
    EXPECT_NEAR(resolution.at("validated_reduced_depth").get<double>(), 0.25, 1e-12) << resolution;
    EXPECT_NE(resolution.at("warning").get<std::string>().find("grid.resolution"), std::string::npos) << resolution;
    EXPECT_EQ(line.at("error_estimate").at("multiple_scattering").at("warning"), resolution.at("warning")) << line;

    const std::string fine = writeScene("fine.json", albedoOneScene(3.2));
    const Outcome within = runEikon("run " + fine + " --out " + (dir_ / "fine").string() +
                                    " --quiet --set render.error_estimate=true");
    ASSERT_EQ(within.exitCode, 0) << within.output;
    EXPECT_EQ(count(within.output, "lattice"), 0) << within.output;
    const nlohmann::json fineLine = readReport(dir_ / "fine" / "report.jsonl").at(0);
    const nlohmann::json& fineResolution = fineLine.at("multiple_scattering").at("voxel_resolution");
    EXPECT_EQ(fineResolution.at("coarse_voxels").get<int>(), 0) << fineResolution;
    EXPECT_NEAR(fineResolution.at("coarsest_reduced_depth").get<double>(), 0.2, 1e-6) << fineResolution;
    EXPECT_FALSE(fineResolution.contains("warning")) << fineResolution;
    EXPECT_FALSE(fineLine.at("error_estimate").contains("multiple_scattering")) << fineLine;
}

// ---- Memory -----------------------------------------------------------------

struct MeasuredRun {
    int exitCode = -1;
    std::string output;          // stdout and stderr together
    long peakResidentKiB = 0;    // the process's peak resident set (wait4)
};

// `eikon run` with EIKON_MEMORY_LIMIT_MB set, its peak memory measured.
MeasuredRun runUnderLimit(const std::vector<std::string>& runArguments, const std::string& limitMiB) {
    std::vector<std::string> arguments{EIKON_EXECUTABLE, "run"};
    arguments.insert(arguments.end(), runArguments.begin(), runArguments.end());
    int readEnd = -1;
    const pid_t child =
        eikon::test::spawnCapturingOutput(arguments, {{"EIKON_MEMORY_LIMIT_MB", limitMiB}}, readEnd);
    MeasuredRun run;
    char buffer[4096];
    for (ssize_t got; (got = read(readEnd, buffer, sizeof buffer)) > 0;) run.output.append(buffer, got);
    close(readEnd);
    int status = 0;
    rusage usage{};
    wait4(child, &status, 0, &usage);
    run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.peakResidentKiB = usage.ru_maxrss;
    return run;
}

// A glass sphere over a floor, 16³ cells; `renderKeys` are added to its render section.
std::string sphereScene(const std::string& renderKeys = "") {
    return R"({
  "grid": {"resolution": [16, 16, 16], "bounds": {"min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5]}},
  "medium": {"index": 1.0},
  "objects": [{"type": "sphere", "center": [0, 0.5, 0], "radius": 0.2, "index": 1.5}],
  "lights": [{"type": "point", "position": [0, 1.5, 0], "power": [10, 10, 10]}],
  "receivers": [{"type": "plane", "point": [0, 0.05, 0], "normal": [0, 1, 0], "size": 1.0, "resolution": 32}],
  "camera": {"position": [0, 1, 2], "target": [0, 0.3, 0], "up": [0, 1, 0], "fov_deg": 45},
  "render": {"photons": 4096, "width": 32, "height": 24, "seed": 3, "error_estimate": false)" +
           renderKeys + "}\n}";
}

// A Radiance .hdr of width × height pixels of radiance 1, run-length
// encoded (four channels of runs of at most 127 bytes a scanline): a few
// MiB on disk for an image whose float decoding takes gigabytes.
void writeFlatHdr(const fs::path& path, int width, int height) {
    std::ofstream out(path, std::ios::binary);
    out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " << height << " +X " << width << "\n";
    const unsigned char rgbe[4] = {128, 128, 128, 129};  // 0.5·2^(129−128) = 1
    std::string scanline = {2, 2, static_cast<char>(width >> 8), static_cast<char>(width & 255)};
    for (unsigned char value : rgbe)
        for (int left = width; left > 0; left -= 127) {
            scanline += static_cast<char>(128 + std::min(left, 127));
            scanline += static_cast<char>(value);
        }
    for (int row = 0; row < height; ++row) out << scanline;
}

// The refusal of a size past the limit: exit code 2, one line naming the
// scene file, the key, the bytes needed and the limit, no output folder,
// and a peak memory of the process far below what the old path allocated
// (gigabytes) before it refused or was killed.
void expectRefusedEarly(const MeasuredRun& run, const std::string& key, const fs::path& out, long boundKiB) {
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_EQ(std::count(run.output.begin(), run.output.end(), '\n'), 1) << run.output;
    EXPECT_NE(run.output.find(key), std::string::npos) << run.output;
    EXPECT_NE(run.output.find(" MiB (EIKON_MEMORY_LIMIT_MB)"), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_LT(run.peakResidentKiB, boundKiB) << run.output;
}

// Documented sizes that cost gigabytes, under a limit of 1 GiB: a 512³
// grid (4.2 GB of fields before the driver refused its octree), caustic
// maps of 4096² texels (4.7 GB before GL_OUT_OF_MEMORY), an 8192²
// environment map (4.4 GB decoded and uploaded): each refused from the
// parsed scene, the process under 256 MiB. The scene itself still runs
// under that limit.
TEST_F(CliLimits, SizesPastTheMemoryLimitAreRefusedBeforeTheyAreAllocated) {
    const std::string scene = writeScene("sphere.json", sphereScene());
    const fs::path out = dir_ / "out";
    const long bound = 256 * 1024;

    const MeasuredRun grid = runUnderLimit({scene, "--out", out.string(), "--quiet", "--set",
                                            "grid.resolution=[512,512,512]"}, "1024");
    expectRefusedEarly(grid, "sphere.json: grid.resolution: expected sizes whose memory fits 1024 MiB", out, bound);
    EXPECT_NE(grid.output.find("the fields over 512×512×512 cells, at least "), std::string::npos) << grid.output;

    const MeasuredRun caustics = runUnderLimit({scene, "--out", out.string(), "--quiet", "--set",
                                                "render.method=\"image_space\"", "--set",
                                                "render.caustic_map_texels=4096"}, "1024");
    expectRefusedEarly(caustics, "sphere.json: render.caustic_map_texels: expected sizes whose memory fits", out,
                       bound);
    EXPECT_NE(caustics.output.find("the caustic maps of 4096² texels"), std::string::npos) << caustics.output;

    writeFlatHdr(dir_ / "sky.hdr", 8192, 8192);
    const std::string environment = writeScene(
        "environment.json", sphereScene(R"(, "environment": {"type": "hdr", "path": "sky.hdr"})"));
    const MeasuredRun sky = runUnderLimit({environment, "--out", out.string(), "--quiet"}, "1024");
    expectRefusedEarly(sky, "environment.json: render.environment.path: expected an image whose decoding fits 1024 MiB",
                       out, bound);

    const MeasuredRun fits = runUnderLimit({scene, "--out", out.string(), "--quiet"}, "1024");
    EXPECT_EQ(fits.exitCode, 0) << fits.output;
}

// A sparse OpenVDB file of 1000 voxels, each in nodes of its own: a few MiB
// on disk, about 300 MiB as OpenVDB reads it (the campaign's 194 MB file
// scattered so took 6.1 GB). Under a limit of 128 MiB it is refused as the
// grid is about to be read, naming the grid and its nodes; the process stays
// under 96 MiB.
TEST_F(CliLimits, ASparseVolumeWhoseTreePassesTheLimitIsRefusedBeforeItIsRead) {
    eikon::test::writeScatteredVdbFile(dir_ / "scattered.vdb", "density", 10);
    std::string text = sphereScene();
    text.insert(text.rfind('}'), R"(, "volume": {"path": "scattered.vdb", "density_extinction": 0.5})");
    const std::string volume = writeScene("volume.json", text);
    const fs::path out = dir_ / "out";
    const MeasuredRun run = runUnderLimit({volume, "--out", out.string(), "--quiet"}, "128");
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find("scattered.vdb: grid \"density\": expected a grid whose tree fits 128 MiB"),
              std::string::npos)
        << run.output;
    EXPECT_NE(run.output.find("1000 leaves and 2000 internal nodes"), std::string::npos) << run.output;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_LT(run.peakResidentKiB, 96 * 1024) << run.output;
}

// EIKON_MEMORY_LIMIT_MB that is not a whole number of MiB is an error of the
// environment (exit code 1), named.
TEST_F(CliLimits, AMalformedMemoryLimitIsNamed) {
    const std::string scene = writeScene("sphere.json", sphereScene());
    for (const std::string limit : {"lots", "0", "-5", "12x"}) {
        const MeasuredRun run = runUnderLimit({scene, "--out", (dir_ / "out").string(), "--quiet"}, limit);
        EXPECT_EQ(run.exitCode, 1) << limit << ": " << run.output;
        EXPECT_NE(run.output.find("EIKON_MEMORY_LIMIT_MB: expected a whole number of MiB of at least 1, found \"" +
                                  limit + "\""),
                  std::string::npos)
            << run.output;
    }
}

// ---- Cost -------------------------------------------------------------------

// A wavefront of grid_cells 512 starts with over a million patches a frame
// (512² cells of two, in the main wavefront and the glass sphere's reflected
// branch): said once on stderr before the run, and in each frame's report
// beside its start_patches; the default 64 starts with 16 384, unremarked.
TEST_F(CliLimits, AWavefrontThatStartsWithAMillionPatchesIsWarnedOfItsCost) {
    const std::string scene = writeScene("sphere.json", sphereScene());
    const fs::path out = dir_ / "out";
    const Outcome costly = runEikon("run " + scene + " --out " + out.string() + " --frames 2 --quiet" +
                                    " --set 'tracer.estimator=\"wavefront\"' --set tracer.wavefront.grid_cells=512");
    ASSERT_EQ(costly.exitCode, 0) << costly.output;
    EXPECT_EQ(count(costly.output, "eikon: warning:"), 1) << costly.output;
    EXPECT_NE(costly.output.find("the wavefronts start with 1.05 million patches a frame (tracer.wavefront.grid_cells)"),
              std::string::npos)
        << costly.output;
    for (const nlohmann::json& line : readReport(out / "report.jsonl")) {
        const nlohmann::json& wavefront = line.at("photons").at("wavefront");
        EXPECT_EQ(wavefront.at("start_patches").get<long long>(), 512 * 512 * 2 * 2) << wavefront;
        EXPECT_NE(wavefront.at("cost_warning").get<std::string>().find("1.05 million patches"), std::string::npos);
    }

    const Outcome usual = runEikon("run " + scene + " --out " + (dir_ / "usual").string() + " --quiet" +
                                   " --set 'tracer.estimator=\"wavefront\"'");
    ASSERT_EQ(usual.exitCode, 0) << usual.output;
    EXPECT_EQ(count(usual.output, "eikon: warning:"), 0) << usual.output;
    const nlohmann::json wavefront = readReport(dir_ / "usual" / "report.jsonl").at(0).at("photons").at("wavefront");
    EXPECT_EQ(wavefront.at("start_patches").get<long long>(), 64 * 64 * 2 * 2) << wavefront;
    EXPECT_FALSE(wavefront.contains("cost_warning")) << wavefront;
}

}  // namespace
