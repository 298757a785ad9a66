// `eikon converge` as users meet it: a study of a small scene writes its
// CSV, plot (PNG and SVG) and report, its photon ladder's error falls as
// the photons grow and time is spent, and bad arguments exit 2 with a clear
// message having written nothing.
#include "tests/integration/CliRun.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using eikon::test::Outcome;
using eikon::test::runEikon;
using eikon::test::runEikonWithin;

class ConvergeCli : public eikon::test::CliFolderTest {
protected:
    ConvergeCli() : CliFolderTest("eikon_converge_") {}
    void SetUp() override {
        CliFolderTest::SetUp();
        scene_ = (dir_ / "scene.json").string();
        std::ofstream(scene_) << R"({
  "grid": {"resolution": [24, 24, 24], "bounds": {"min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5]}},
  "objects": [{"type": "sphere", "center": [0, 0.5, 0], "radius": 0.2, "index": 1.5}],
  "lights": [{"type": "point", "position": [0, 1.5, 0], "power": [10, 10, 10]}],
  "receivers": [{"type": "plane", "point": [0, 0.05, 0], "normal": [0, 1, 0], "size": 1.0, "resolution": 32}],
  "camera": {"position": [0, 1, 2], "target": [0, 0.3, 0], "up": [0, 1, 0], "fov_deg": 45},
  "render": {"photons": 16384, "width": 48, "height": 36, "seed": 3}
})";
    }
    std::string scene_;
};

std::string readAll(const fs::path& path) {
    std::stringstream text;
    text << std::ifstream(path).rdbuf();
    return text.str();
}

TEST_F(ConvergeCli, StudyWritesItsFilesAndThePhotonLadderConverges) {
    const fs::path out = dir_ / "study";
    const Outcome outcome = runEikon("converge " + scene_ + " --out " + out.string() + " --budget-s 60",
                                     "LP_NUM_THREADS=2");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    for (const char* file : {"converge.csv", "converge.png", "converge.svg", "converge.md"})
        EXPECT_TRUE(fs::exists(out / file)) << file;
    EXPECT_GT(fs::file_size(out / "converge.png"), 10000u);

    std::ifstream csv(out / "converge.csv");
    std::string header, row;
    std::getline(csv, header);
    EXPECT_EQ(header, "knob,setting,photons_factor,step_factor,grid_factor,run_time_s,receivers_relative_l1,"
                      "image_relative_l1,fluence_relative_l1");
    std::map<double, double> photonError;  // photons factor → receivers' error
    int rows = 0;
    while (std::getline(csv, row)) {
        ++rows;
        EXPECT_EQ(row.find("nan"), std::string::npos) << row;
        const std::vector<std::string> cells = eikon::test::csvCells(row);
        ASSERT_EQ(cells.size(), 9u) << row;
        if ((cells[0] == "photons" || cells[0] == "scene") && !cells[6].empty())
            photonError[std::stod(cells[2])] = std::stod(cells[6]);
    }
    EXPECT_GE(rows, 10) << "the ladders and the reference";
    ASSERT_GE(photonError.size(), 4u);
    EXPECT_LT(photonError.rbegin()->second, 0.6 * photonError.begin()->second)
        << "32x the photons: the noise, which dominates with sharp glass in uniform air, falls (ideally to "
           "1/sqrt(32) of it)";

    const std::string report = readAll(out / "converge.md");
    for (const char* part : {"Cheapest setting for an error", "The reference's own error", "Monte Carlo noise",
                             "Richardson with the integrator's order p = 2", "Left out", "relative L1"})
        EXPECT_NE(report.find(part), std::string::npos) << part;
}

// Each --reference once studied something meaningless or failed late:
// photons=1e300 overflowed to a 1-photon "reference", grid=1e300 was clamped
// to a 4³ grid, grid=1000 ended in std::bad_alloc, and a reference coarser
// than the scene compared every rung with a worse one.
TEST_F(ConvergeCli, ReferenceOutsideItsRangeOrCoarserThanARungIsRefused) {
    const fs::path out = dir_ / "never";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"photons=1e300", "--reference: expected photons=F with F at most 1024, found photons=1e300"},
        {"step=1e300", "--reference: expected step=F with F at most 64, found step=1e300"},
        {"grid=1e300", "--reference: expected grid=F with F at most 4, found grid=1e300"},
        {"grid=1000", "--reference: expected grid=F with F at most 4, found grid=1000"},
        {"photons=0", "--reference: expected a reference finer than every rung of the study: photons=F with F >= 1 "
                      "(the rung \"scene\", the scene's own settings, has photons=1), found photons=0"},
        {"photons=16,step=0.5", "the rung \"scene\", the scene's own settings, has step=1), found step=0.5"},
        {"photons=1,grid=1", "--reference: expected a reference finer than the scene's own settings (the rung "
                             "\"scene\") in at least one knob"}};
    for (const auto& [reference, message] : cases) {
        const Outcome outcome = runEikonWithin(300, "converge " + scene_ + " --out " + out.string() + " --reference " +
                                                        reference);
        EXPECT_EQ(outcome.exitCode, 2) << reference << "\n" << outcome.output;
        EXPECT_NE(outcome.output.find(message), std::string::npos) << reference << "\n" << outcome.output;
        EXPECT_FALSE(fs::exists(out)) << reference;
    }
}

// A reference within its range whose scene the scene file could not hold
// is refused as the file would be, before any rung renders: past the cells
// a grid may have (it allocated them before), past the photons a frame may
// trace (it overflowed), and finer than the wavefront's thresholds go.
TEST_F(ConvergeCli, ReferenceTheSceneFileCouldNotHoldIsRefused) {
    const fs::path out = dir_ / "never";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"--set grid.resolution=[130,130,130] --reference grid=4",
         "--reference: the reference's grid.resolution=[520,520,520] is refused as the scene file would be: " + scene_ +
             ": grid.resolution: expected at most 134217728 cells (512^3) in total"},
        {"--set render.photons=1000000000 --reference photons=16",
         "--reference: the reference's render.photons=16000000000 is refused as the scene file would be: " + scene_ +
             ": render.photons: expected an integer in [1, 2147483647]"},
        {"--set 'tracer.estimator=\"wavefront\"' --set tracer.wavefront.split_texels=0.4 --set tracer.wavefront.tear_texels=0.4 "
         "--set tracer.wavefront.split_voxels=0.4 --reference photons=16",
         "--reference: expected photons=F with F at most 8 for this scene (its wavefront split and tear thresholds, "
         "refined further, stay at 0.05), found photons=16"}};
    for (const auto& [arguments, message] : cases) {
        const Outcome outcome =
            runEikonWithin(300, "converge " + scene_ + " --out " + out.string() + " " + arguments, "LP_NUM_THREADS=2");
        EXPECT_EQ(outcome.exitCode, 2) << arguments << "\n" << outcome.output;
        EXPECT_NE(outcome.output.find(message), std::string::npos) << arguments << "\n" << outcome.output;
        EXPECT_FALSE(fs::exists(out)) << arguments;
    }
}

// --frame 500 of a live fluid scene: every frame before it is simulated
// first (once per rung, before), far past a 20 s budget. The study times
// the first frame and refuses with what it would need.
TEST_F(ConvergeCli, ABudgetThatCannotReachTheFrameOfAFluidSceneIsRefused) {
    const fs::path out = dir_ / "never";
    const Outcome outcome = runEikonWithin(300, "converge " + std::string(EIKON_SOURCE_DIR) +
                                                    "/scenes/hot_plate_plume.json --frame 500 --budget-s 20 --out " +
                                                    out.string(),
                                           "LP_NUM_THREADS=2");
    EXPECT_EQ(outcome.exitCode, 2) << outcome.output;
    EXPECT_NE(outcome.output.find("eikon: error: --budget-s: expected at least "), std::string::npos)
        << outcome.output;
    EXPECT_NE(outcome.output.find(" s for --frame 500, or a --frame below "), std::string::npos) << outcome.output;
    EXPECT_NE(outcome.output.find("s a frame, measured over frame 1"), std::string::npos) << outcome.output;
    EXPECT_NE(outcome.output.find("found 20 s"), std::string::npos) << outcome.output;
    EXPECT_FALSE(fs::exists(out));
}

TEST_F(ConvergeCli, BadArgumentsExitTwoAndWriteNothing) {
    const fs::path out = dir_ / "never";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"converge --out " + out.string(), "scene"},
        {"converge " + scene_ + " --out " + out.string() + " --budget-s 0", "--budget-s: expected a number of seconds > 0"},
        {"converge " + scene_ + " --out " + out.string() + " --budget-s -5", "--budget-s"},
        {"converge " + scene_ + " --out " + out.string() + " --outputs receivers,colour", "--outputs: expected receivers, image or fluence"},
        {"converge " + scene_ + " --out " + out.string() + " --outputs fluence", "--outputs: expected an output the scene has"},
        {"converge " + scene_ + " --out " + out.string() + " --reference photons=two", "--reference: expected photons=F"},
        {"converge " + scene_ + " --out " + out.string() + " --reference photons=inf", "--reference: expected photons=F"},
        {"converge " + (dir_ / "missing.json").string() + " --out " + out.string(), "missing.json"}};
    for (const auto& [arguments, message] : cases) {
        const Outcome outcome = runEikon(arguments);
        EXPECT_EQ(outcome.exitCode, 2) << arguments << "\n" << outcome.output;
        EXPECT_NE(outcome.output.find(message), std::string::npos) << arguments << "\n" << outcome.output;
        EXPECT_FALSE(fs::exists(out)) << arguments;
    }
}

}  // namespace
