// The fluid solver's frames through `eikon run`: a stiff flow ends with a
// clear message instead of running on for hours, and each simulated frame's
// report line says how many substeps it took, how far its fastest flow moved
// in one, and what its sources put in.
#include "tests/integration/CliRun.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using eikon::test::Outcome;
using eikon::test::readReport;
using eikon::test::runEikonWithin;

class FluidCli : public eikon::test::CliFolderTest {
protected:
    FluidCli() : CliFolderTest("eikon_fluid_cli_") {}
};

// A 0.5 m closed box over a plate 200 K above ambient, thermal_expansion
// 1000/K and no viscosity: buoyancy g·β·ΔT ≈ 2·10⁶ m/s² (issue 56's case).
const char* const kStiffScene = R"({
  "grid": {"resolution": [16, 16, 16], "bounds": {"min": [-0.25, 0.0, -0.25], "max": [0.25, 0.5, 0.25]}},
  "lights": [{"type": "directional", "direction": [0.0, -1.0, 0.0], "irradiance": [1.0, 1.0, 1.0]}],
  "camera": {"position": [0.0, 0.25, 2.0], "target": [0.0, 0.25, 0.0], "up": [0, 1, 0], "fov_deg": 20},
  "render": {"photons": 4096, "width": 32, "height": 24, "error_estimate": false},
  "sim": {
    "resolution": [12, 12, 12], "thermal_expansion": 1000, "viscosity": 0,
    "sources": [{"type": "hot_plate", "min": [-0.1, 0.0, -0.1], "max": [0.1, 0.05, 0.1], "temperature": 493.15}]
  }
})";

// Frame 1 starts at rest (one substep) and comes out moving thousands of
// cells a substep: flagged. Frame 2 would need tens of thousands of
// substeps: the run stops there with exit code 2, the count and what to change.
TEST_F(FluidCli, StiffFlowEndsWithAClearMessage) {
    const std::string scene = writeScene("stiff.json", kStiffScene);
    const Outcome refused = runEikonWithin(120, "run " + scene + " --out " + (dir_ / "refused").string() + " --frames 4");
    EXPECT_EQ(refused.exitCode, 2) << refused.output;
    EXPECT_NE(refused.output.find("sim.max_substeps: expected at most 1000 substeps in a frame, found frame 2 needs "),
              std::string::npos)
        << refused.output;
    EXPECT_NE(refused.output.find("raise sim.max_substeps or sim.cfl"), std::string::npos) << refused.output;

    const Outcome flagged = runEikonWithin(120, "run " + scene + " --out " + (dir_ / "flagged").string() + " --frames 2");
    ASSERT_EQ(flagged.exitCode, 0) << flagged.output;
    EXPECT_NE(flagged.output.find("eikon: warning: frame 1: the fastest flow crossed "), std::string::npos)
        << flagged.output;
    const auto report = readReport(dir_ / "flagged" / "report.jsonl");
    ASSERT_EQ(report.size(), 2u);
    EXPECT_FALSE(report[0].contains("fluid")) << "frame 0 is the initial state";
    const nlohmann::json& fluid = report[1]["fluid"];
    EXPECT_EQ(fluid["substeps"], 1);
    EXPECT_GT(fluid["cells_per_substep"].get<double>(), 5.0);
    EXPECT_TRUE(fluid.contains("fast_flow_warning")) << fluid.dump();
    EXPECT_GT(fluid["budgets"]["heat"]["sources"].get<double>(), 0.0) << fluid.dump();
}

// A gentle plume with the limit lowered under what its frames need: refused
// with the scene's own limit; with sim.max_substeps raised it runs, and its
// report carries the substeps and the heat budget: the change of the total
// from frame to frame is what the sources put in and advection changed, and
// in a closed box advection changes next to nothing.
TEST_F(FluidCli, MaxSubstepsIsTheLimitAndTheReportCarriesTheBudget) {
    const std::string scene = writeScene("gentle.json", kStiffScene);
    const std::string gentle = " --set sim.thermal_expansion=0.0034 --set sim.viscosity=1.5e-5 --set sim.substeps=3";
    const Outcome refused = runEikonWithin(
        120, "run " + scene + " --out " + (dir_ / "refused").string() + " --frames 2" + gentle + " --set sim.max_substeps=2");
    EXPECT_EQ(refused.exitCode, 2) << refused.output;
    EXPECT_NE(refused.output.find("sim.max_substeps: expected at least sim.substeps (3), found 2"), std::string::npos)
        << refused.output;

    const Outcome ran = runEikonWithin(
        120, "run " + scene + " --out " + (dir_ / "ran").string() + " --frames 4" + gentle + " --set sim.max_substeps=3");
    ASSERT_EQ(ran.exitCode, 0) << ran.output;
    EXPECT_EQ(ran.output.find("warning"), std::string::npos) << ran.output;
    const auto report = readReport(dir_ / "ran" / "report.jsonl");
    ASSERT_EQ(report.size(), 4u);
    double previous = 0.0;  // Σ (T − T_amb)·V at frame 0 is the plate's own cells, as frame 1's total less its gain
    for (std::size_t frame = 1; frame < report.size(); ++frame) {
        const nlohmann::json& fluid = report[frame]["fluid"];
        EXPECT_EQ(fluid["substeps"], 3);
        EXPECT_FALSE(fluid.contains("fast_flow_warning"));
        const nlohmann::json& heat = fluid["budgets"]["heat"];
        EXPECT_EQ(heat["unit"], "K m3");
        const double gained = heat["sources"].get<double>() + heat["advection"].get<double>();
        if (frame > 1) {
            EXPECT_NEAR(heat["total"].get<double>() - previous, gained, 1e-9 * heat["total"].get<double>());
        }
        // A closed box: advection moves heat, the mass correction puts back
        // what the limiter took (all but 0.7% of frame 1's gain, when every
        // cell is still at the plate's or the ambient temperature and it has
        // no front to put it on; 1e-10 after).
        EXPECT_NEAR(heat["advection"].get<double>(), 0.0, 0.01 * heat["sources"].get<double>()) << frame;
        previous = heat["total"].get<double>();
    }
}

}  // namespace
