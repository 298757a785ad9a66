// An OpenVDB sequence as Blender writes it (fluid_data_####.vdb with density,
// temperature, flame, velocity), imported through the scene's `volume`
// section and stepped one file per frame: the index follows Gladstone–Dale of
// the mapped temperature, extinction and scattering follow density.
#include "bridge/core/Error.h"
#include "io/scene/SceneParser.h"
#include "sim/SceneFields.h"
#include "sim/optics/AirOptics.h"
#include "sim/volume/VolumeSequence.h"
#include "tests/unit/VdbTestFiles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace eikon::sim {
namespace {

namespace fs = std::filesystem;
using test::VdbTestGrid;

// Frame number f of the sequence: temperature t = f·(x + 0.5) (Blender's
// unitless heat), density f/2 (half floats: exact), flame 0.25 where x > 0,
// velocity (f, 0, 0). All linear, so trilinear sampling inside the active box is exact.
void writeBlenderFrame(const fs::path& folder, int f) {
    char name[64];
    std::snprintf(name, sizeof name, "fluid_data_%04d.vdb", f);
    const std::vector<VdbTestGrid> grids{
        {"density", 1, [f](double, double, double, int) { return 0.5f * float(f); }, true},
        {"temperature", 1, [f](double x, double, double, int) { return float(f * (x + 0.5)); }},
        {"flame", 1, [](double, double, double, int) { return 0.0f; }},
        {"velocity", 3, [f](double, double, double, int c) { return c == 0 ? float(f) : 0.0f; }}};
    test::writeVdbFile(folder / name, grids, 0.025, -0.3, 0.3);
}

class VolumeSequenceTest : public ::testing::Test {
protected:
    void SetUp() override {
        folder_ = fs::path(::testing::TempDir()) /  // one per test: ctest runs tests in parallel
                  ("eikon_blender_sequence_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(folder_);
        fs::create_directories(folder_);
        for (int f = 1; f <= 3; ++f) writeBlenderFrame(folder_, f);
    }
    Scene scene(const std::string& volumeJson) const {
        nlohmann::json root = nlohmann::json::parse(R"({
          "grid": {"resolution": [8, 4, 4], "bounds": {"min": [-0.2, -0.1, -0.1], "max": [0.2, 0.1, 0.1]}},
          "medium": {"index": 1.000273},
          "lights": [{"type": "point", "position": [0, 1, 0], "power": 1}]})");
        root["volume"] = nlohmann::json::parse(volumeJson);
        return parseScene(root, (folder_ / "scene.json").string());
    }
    void TearDown() override { fs::remove_all(folder_); }
    fs::path folder_;
};

TEST_F(VolumeSequenceTest, ThreeFramesFollowTheMapping) {
    const Scene s = scene(R"({"path": "fluid_data_####.vdb", "frame_start": 1, "frame_time": 0.04,
        "grids": {"flame": "flame", "velocity": "velocity"},
        "density_extinction": [2, 4, 6], "density_scattering": [1, 1, 1],
        "ambient_temperature": 293.15, "temperature_scale": 100, "flame_temperature": 500})");
    SceneFields fields(s);
    EXPECT_TRUE(fields.changesOverTime());
    const GladstoneDale air;  // the volume's defaults: 2.93e-4 at 273.15 K and 1 atm
    std::uint64_t indexVersion = 0;
    for (int frame = 0; frame < 3; ++frame) {
        SCOPED_TRACE("frame " + std::to_string(frame));
        if (frame > 0) fields.advanceFrame();
        const int f = frame + 1;  // the file shown
        EXPECT_DOUBLE_EQ(fields.time(), 0.04 * frame);
        const FieldSet& set = fields.fields();
        EXPECT_GT(set.indexVersion, indexVersion);
        indexVersion = set.indexVersion;
        ASSERT_TRUE(set.hasExtinction());
        ASSERT_TRUE(set.hasScattering());
        for (int k = 0; k < 4; ++k)
            for (int j = 0; j < 4; ++j)
                for (int i = 0; i < 8; ++i) {
                    const glm::dvec3 x = set.grid.cellCentre(i, j, k);
                    const std::size_t c = set.grid.linearIndex(i, j, k);
                    const double temperature = 293.15 + 100.0 * f * (x.x + 0.5);
                    const double expected = (1.000273 - set.referenceIndex) + air.refractivityAt(temperature, 101325.0) -
                                            air.refractivityAt(293.15, 101325.0);
                    // float32 δn near 1e-5 and float32 temperature samples: 1e-9 absolute.
                    EXPECT_NEAR(set.deltaIndex[c], expected, 1e-9) << i << " " << j << " " << k;
                    EXPECT_FLOAT_EQ(set.extinction[3 * c + 0], 2.0f * 0.5f * f);
                    EXPECT_FLOAT_EQ(set.extinction[3 * c + 2], 6.0f * 0.5f * f);
                    EXPECT_FLOAT_EQ(set.scattering[3 * c + 1], 0.5f * f);
                }
        // Hotter frames have a lower index at the hot end (Gladstone–Dale: n − 1 ∝ 1/T).
        EXPECT_LT(set.deltaIndex[set.grid.linearIndex(7, 0, 0)], set.deltaIndex[set.grid.linearIndex(0, 0, 0)]);
        const auto arrays = fields.exportArrays();
        ASSERT_EQ(arrays.size(), 4u);
        EXPECT_EQ(arrays[0].name, "density");
        EXPECT_EQ(arrays[1].name, "temperature");
        EXPECT_EQ(arrays[2].name, "flame");
        EXPECT_EQ(arrays[3].name, "velocity");
        EXPECT_FLOAT_EQ(arrays[3].values[0], float(f));
    }
}

TEST_F(VolumeSequenceTest, MissingGridOrFileIsAnInputError) {
    try {
        SceneFields fields(scene(R"({"path": "fluid_data_####.vdb", "grids": {"temperature": "heat"}})"));
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("fluid_data_0001.vdb: expected a grid named \"heat\", found the grids "
                                                 "\"density\", \"temperature\", \"flame\", \"velocity\""),
                  std::string::npos)
            << error.what();
    }
    SceneFields fields(scene(R"({"path": "fluid_data_####.vdb", "frame_start": 2})"));
    fields.advanceFrame();  // file 3
    try {
        fields.advanceFrame();  // file 4 does not exist
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("fluid_data_0004.vdb: expected an OpenVDB file, found no such file"),
                  std::string::npos)
            << error.what();
    }
}

// Before frame 0 is written, the files of the later frames are checked as
// far as their voxel values (checkVolumeFrames): a file cut short, one that is
// not OpenVDB, one whose last grid's tree is overwritten (its length kept),
// one without a grid the scene reads — each named with the scene file and
// volume.path; the frames before it pass.
TEST_F(VolumeSequenceTest, DamagedLaterFilesAreFoundBeforeFrameZero) {
    const Scene s = scene(R"({"path": "fluid_data_####.vdb", "grids": {"flame": "flame", "velocity": "velocity"}})");
    const GridSpec grid = s.grid.spec();
    EXPECT_NO_THROW(checkVolumeFrames(*s.volume, grid, 3, s.sourcePath));
    const fs::path last = folder_ / "fluid_data_0003.vdb";
    std::string whole;
    {
        std::ifstream in(last, std::ios::binary);
        whole.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    const auto refusal = [&](const std::string& bytes) -> std::string {
        std::ofstream(last, std::ios::binary | std::ios::trunc) << bytes;
        try {
            checkVolumeFrames(*s.volume, grid, 3, s.sourcePath);
        } catch (const InputError& error) {
            return error.what();
        }
        return "no error";
    };
    const std::string named = s.sourcePath + ": volume.path: " + last.string() + ": ";
    EXPECT_EQ(refusal(whole.substr(0, whole.size() - 100)).rfind(named + "byte ", 0), 0u)
        << "the grid table's offsets reach past the end";
    EXPECT_EQ(refusal(std::string(whole.size(), 'x')).rfind(named + "byte 8: expected an OpenVDB file", 0), 0u);
    std::string damaged = whole;
    std::fill(damaged.end() - 400, damaged.end() - 8, '\x55');  // the velocity grid's leaf buffers
    EXPECT_EQ(refusal(damaged).rfind(named + "byte ", 0), 0u) << refusal(damaged);
    test::writeVdbFile(last, {{"density", 1, [](double, double, double, int) { return 1.0f; }}}, 0.025, -0.3, 0.3);
    try {
        checkVolumeFrames(*s.volume, grid, 3, s.sourcePath);
        FAIL() << "a file without the temperature grid passed";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()).rfind(named + "expected a grid named \"temperature\", found the grids "
                                                          "\"density\"",
                                                  0),
                  0u)
            << error.what();
    }
    EXPECT_NO_THROW(checkVolumeFrames(*s.volume, grid, 2, s.sourcePath)) << "frames 0 and 1 read files 1 and 2";
}

}  // namespace
}  // namespace eikon::sim
