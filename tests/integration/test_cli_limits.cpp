// What `eikon run` says where a scene goes past what eikon can compute: a
// multiple-scattering lattice whose voxels are too thick for its float
// arithmetic (render/stages/LatticeScattering.h, the depth limit).
#include "tests/integration/CliRun.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using eikon::test::Outcome;
using eikon::test::runEikon;

class CliLimits : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("eikon_cli_limits_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string writeScene(const std::string& name, const std::string& text) {
        const fs::path path = dir_ / name;
        std::ofstream(path) << text;
        return path.string();
    }
    // Lines of report.jsonl in `out`.
    static std::vector<nlohmann::json> reportLines(const fs::path& out) {
        std::vector<nlohmann::json> lines;
        std::ifstream report(out / "report.jsonl");
        for (std::string line; std::getline(report, line);) lines.push_back(nlohmann::json::parse(line));
        return lines;
    }
    fs::path dir_;
};

int count(const std::string& text, const std::string& what) {
    int found = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++found;
    return found;
}

// A medium of albedo 1 on 16³ voxels of 1/16 m, lit from above, its light
// diffused on the lattice: `extinction` 640/m is an optical depth of 40 per
// voxel, far past the limit of 14 on 14 links; 32/m is 2.
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
// run, with the depth found, the limit and what to change.
TEST_F(CliLimits, LatticeBeyondItsDepthLimitIsWarnedAndNotConverged) {
    const std::string thick = writeScene("thick.json", albedoOneScene(640.0));
    const Outcome outcome = runEikon("run " + thick + " --out " + (dir_ / "thick").string() + " --frames 2 --quiet");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    EXPECT_EQ(count(outcome.output, "eikon: warning:"), 1) << outcome.output;
    EXPECT_NE(outcome.output.find("optical depth up to 40 across a voxel, beyond its limit of 14"), std::string::npos)
        << outcome.output;
    EXPECT_NE(outcome.output.find("grid.resolution"), std::string::npos) << outcome.output;
    const std::vector<nlohmann::json> lines = reportLines(dir_ / "thick");
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
    EXPECT_EQ(count(within.output, "eikon: warning:"), 0) << within.output;
    const nlohmann::json lattice = reportLines(dir_ / "thin").at(0).at("multiple_scattering");
    EXPECT_TRUE(lattice.at("converged").get<bool>()) << lattice;
    EXPECT_EQ(lattice.at("depth_limit").at("voxels_beyond").get<int>(), 0) << lattice;
    EXPECT_FALSE(lattice.at("depth_limit").contains("warning")) << lattice;
}

}  // namespace
