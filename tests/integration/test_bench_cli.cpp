// `eikon bench`'s per-kernel figures and `eikon warm-shaders`, run as a user
// runs them. No timing is asserted: the bench's counts are checked against
// the frame report of `eikon run` on the same scene and settings, and its
// times per unit against its own times and counts.
#include "tests/integration/CliRun.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using eikon::test::Outcome;
using eikon::test::runEikon;

class BenchCli : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("eikon_cli_bench_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
                "_" + std::to_string(getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    fs::path writeScene(const std::string& text) const {
        const fs::path scene = dir_ / "scene.json";
        std::ofstream(scene) << text;
        return scene;
    }

    // `eikon bench` at the scene's own 16³ and 4096 photons, one timed
    // frame; its JSON.
    nlohmann::json bench(const fs::path& scene) const {
        const fs::path out = dir_ / "bench.json";
        const std::string arguments =
            "bench " + scene.string() + " --resolution 16 --photons 4096 --repeats 1 --out " + out.string();
        const Outcome outcome = runEikon(arguments, "LP_NUM_THREADS=2");
        EXPECT_EQ(outcome.exitCode, 0) << outcome.output;
        EXPECT_NE(outcome.output.find("ns/unit"), std::string::npos) << outcome.output;
        std::ifstream file(out);
        return nlohmann::json::parse(file);
    }

    // Frame 0's report line of `eikon run` on the same scene.
    nlohmann::json report(const fs::path& scene) const {
        const Outcome outcome =
            runEikon("run " + scene.string() + " --quiet --out " + (dir_ / "run").string(), "LP_NUM_THREADS=2");
        EXPECT_EQ(outcome.exitCode, 0) << outcome.output;
        return eikon::test::readReport(dir_ / "run" / "report.jsonl").at(0);
    }

    fs::path dir_;
};

// The kernel's row for `unit`; fails the test where there is none.
nlohmann::json row(const nlohmann::json& bench, const std::string& kernel, const std::string& unit) {
    for (const nlohmann::json& figure : bench.at("kernels"))
        if (figure.at("kernel") == kernel && figure.at("unit") == unit) return figure;
    ADD_FAILURE() << "no " << kernel << " row per " << unit << " in " << bench.at("kernels").dump(1);
    return nlohmann::json::object({{"count", 0}, {"ms", 0.0}, {"measured", false}});
}

// Every measured row: a positive time per unit that is its time over its count.
void expectTimesPerUnitDivide(const nlohmann::json& bench) {
    for (const nlohmann::json& figure : bench.at("kernels")) {
        if (!figure.at("measured").get<bool>()) {
            EXPECT_FALSE(figure.at("reason").get<std::string>().empty()) << figure.dump();
            continue;
        }
        const auto count = figure.at("count").get<std::uint64_t>();
        const double ms = figure.at("ms").get<double>();
        ASSERT_GT(count, 0u) << figure.dump();
        EXPECT_GT(figure.at("ns_per_unit").get<double>(), 0.0) << figure.dump();
        EXPECT_NEAR(figure.at("ns_per_unit").get<double>() * static_cast<double>(count), ms * 1e6, ms * 1e6 * 1e-12)
            << figure.dump();
    }
}

TEST_F(BenchCli, EachPhotonKernelHasTheRunsCountAndATimePerUnit) {
    const fs::path scene = writeScene(eikon::test::kSmallSphereScene);  // 16³, 4096 photons, 32 × 24
    const nlohmann::json bench = this->bench(scene);
    const nlohmann::json run = report(scene);
    expectTimesPerUnitDivide(bench);
    EXPECT_EQ(row(bench, "photons", "photon").at("count"), run.at("photons").at("emitted"));
    EXPECT_EQ(row(bench, "photons", "step").at("count"), run.at("photons").at("steps"));
    EXPECT_TRUE(row(bench, "photons", "photon").at("measured").get<bool>());
    EXPECT_EQ(row(bench, "view", "camera ray").at("count"), 32 * 24 * 4);  // render.samples_per_pixel 4
    EXPECT_TRUE(row(bench, "view", "camera ray").at("measured").get<bool>());
    EXPECT_EQ(row(bench, "post", "pixel").at("count"), 32 * 24);
    EXPECT_EQ(row(bench, "fluence", "cell").at("count"), 16 * 16 * 16);
    // Uniform air around an analytic sphere: no gradient and no step
    // structure to compute, said as the run's report says it.
    const nlohmann::json prepare = row(bench, "prepare", "cell");
    EXPECT_EQ(prepare.at("count"), 16 * 16 * 16);
    EXPECT_FALSE(prepare.at("measured").get<bool>());
    for (const nlohmann::json& stage : run.at("stages")) {
        if (stage.at("name") == "prepare") {
            EXPECT_EQ(prepare.at("reason"), "not run: " + stage.at("reason").get<std::string>());
        }
        if (stage.at("name") == "photons") {
            EXPECT_EQ(row(bench, "photons", "photon").at("device"), stage.at("device"));
        }
    }
}

TEST_F(BenchCli, TheWavefrontsRaysAndPatchesAreTheRunsCounts) {
    std::string text = eikon::test::kSmallSphereScene;
    const std::string last = "\"seed\": 3}";
    text.replace(text.find(last), last.size(), last + ",\n  \"tracer\": {\"estimator\": \"wavefront\"}");
    const fs::path scene = writeScene(text);
    const nlohmann::json bench = this->bench(scene);
    const nlohmann::json run = report(scene);
    expectTimesPerUnitDivide(bench);
    const nlohmann::json& wavefront = run.at("photons").at("wavefront");
    ASSERT_GT(wavefront.at("rays").get<std::uint64_t>(), 0u);
    EXPECT_EQ(row(bench, "photons", "ray").at("count"), wavefront.at("rays"));
    EXPECT_EQ(row(bench, "photons", "patch").at("count"), wavefront.at("patches"));
    EXPECT_EQ(row(bench, "photons", "step").at("count"), run.at("photons").at("steps"));
}

// The build runs `eikon warm-shaders scenes/default.json` so that a fresh
// machine's first run finds its programs compiled. With a cache of its own,
// the run after it adds nothing to Mesa's cache: every program it compiles
// was compiled by warm-shaders, with the same options. And it writes nothing.
TEST_F(BenchCli, AfterWarmShadersTheRunCompilesNothingNew) {
    const fs::path scene = writeScene(eikon::test::kSmallSphereScene);
    const fs::path cache = dir_ / "cache";
    const std::string environment = "LP_NUM_THREADS=2 MESA_SHADER_CACHE_DIR=" + cache.string();
    const auto cacheFiles = [&] {
        std::size_t files = 0;
        if (fs::exists(cache))
            for (const auto& entry : fs::recursive_directory_iterator(cache)) files += entry.is_regular_file();
        return files;
    };
    const fs::path workDir = dir_ / "cwd";
    fs::create_directories(workDir);
    const Outcome warm =
        runEikon("warm-shaders " + fs::absolute(scene).string(), "cd " + workDir.string() + " && " + environment);
    ASSERT_EQ(warm.exitCode, 0) << warm.output;
    EXPECT_TRUE(fs::is_empty(workDir)) << "warm-shaders wrote into its working folder";
    const std::size_t warmed = cacheFiles();
    if (warmed == 0) GTEST_SKIP() << "this driver keeps no shader cache in MESA_SHADER_CACHE_DIR";
    const Outcome run = runEikon("run " + scene.string() + " --quiet --out " + (dir_ / "run").string(), environment);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(cacheFiles(), warmed) << "the run compiled programs that warm-shaders did not";
}

TEST_F(BenchCli, WarmShadersRefusesAMissingSceneByName) {
    const Outcome outcome = runEikon("warm-shaders " + (dir_ / "missing.json").string(), "LP_NUM_THREADS=2");
    EXPECT_EQ(outcome.exitCode, 2) << outcome.output;
    EXPECT_NE(outcome.output.find("missing.json"), std::string::npos) << outcome.output;
}

}  // namespace
