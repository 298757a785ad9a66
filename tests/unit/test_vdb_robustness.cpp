// A seeded corpus of damaged inputs: truncated, bit-flipped and hostile
// (extreme sizes, counts and offsets written over the fields OpenVDB trusts)
// .vdb files, and damaged scene files. Each one must end in an InputError
// message or, where the damage happens to leave a valid file (a flipped bit
// in a value), in a successful read with finite samples — never in a crash,
// a hang or another exception. Run under AddressSanitizer and UBSan in CI
// (label "sanitize"). Deterministic: a fixed seed.
#include "bridge/core/Error.h"
#include "io/vdb/VdbVolumeFile.h"
#include "io/scene/SceneParser.h"
#include "tests/unit/VdbTestFiles.h"

#include <gtest/gtest.h>

#include <iostream>

#include <cmath>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>

namespace eikon::io {
namespace {

namespace fs = std::filesystem;
using test::VdbTestGrid;

std::string readAll(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

void writeAll(const fs::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

struct Tally {
    int errors = 0;    // ended in an InputError
    int readable = 0;  // still a valid file: read with finite samples
};

// Opens `bytes` as a .vdb and samples every grid the Blender scene reads.
void tryVdb(const fs::path& path, const std::string& bytes, const std::string& label, Tally& tally) {
    writeAll(path, bytes);
    const GridSpec render{{4, 4, 4}, glm::dvec3(0.02), glm::dvec3(0.2)};
    try {
        const VdbVolumeFile file(path);
        for (const char* name : {"density", "temperature"}) {
            for (float v : file.sample(name, 1, render, glm::dvec3(0.0))) ASSERT_TRUE(std::isfinite(v)) << label;
        }
        for (float v : file.sample("velocity", 3, render, glm::dvec3(0.0))) ASSERT_TRUE(std::isfinite(v)) << label;
        ++tally.readable;
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find(path.string()), std::string::npos) << label << ": " << error.what();
        ++tally.errors;
    } catch (const std::exception& error) {
        ADD_FAILURE() << label << ": not an InputError: " << error.what();
    }
}

// Small Blender-like files (one root child per grid: active voxels at
// positive coordinates) in three of the layouts OpenVDB writes: zip, blosc,
// and raw values, each with active-mask compression.
std::vector<std::string> seedFiles(const fs::path& folder) {
    std::vector<std::string> seeds;
    const std::vector<VdbTestGrid> grids{
        {"density", 1, [](double x, double y, double, int) { return float(0.5 + x + y); }, true},
        {"temperature", 1, [](double x, double, double z, int) { return float(2 * x - z); }},
        {"velocity", 3, [](double x, double y, double z, int c) { return float(c == 0 ? y : c == 1 ? z : x); }}};
    for (unsigned compression : {0x3u, 0x6u, 0x2u}) {
        const fs::path path = folder / ("seed" + std::to_string(compression) + ".vdb");
        test::writeVdbFile(path, grids, 0.04, 0.0, 0.24, compression);
        seeds.push_back(readAll(path));
    }
    return seeds;
}

class Robustness : public ::testing::Test {
protected:
    void SetUp() override {
        // One folder per test: ctest runs the tests of this file in parallel processes.
        folder_ = fs::path(::testing::TempDir()) /
                  ("eikon_robustness_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(folder_);
        fs::create_directories(folder_);
    }
    void TearDown() override { fs::remove_all(folder_); }
    fs::path folder_;
};

TEST_F(Robustness, SeedFilesAreReadable) {
    Tally tally;
    const auto seeds = seedFiles(folder_);
    for (std::size_t s = 0; s < seeds.size(); ++s) tryVdb(folder_ / "case.vdb", seeds[s], "seed", tally);
    EXPECT_EQ(tally.readable, static_cast<int>(seeds.size()));
}

// Every proper prefix of a valid file is damaged: each must be an error.
TEST_F(Robustness, TruncatedVdbFilesAreErrors) {
    std::mt19937 random(20261122);
    Tally tally;
    int cases = 0;
    for (const std::string& seed : seedFiles(folder_)) {
        std::vector<std::size_t> lengths{0, 1, 7, 8, 11, 12, 20, 24, 60, 61, 100, 200, 300, 400, seed.size() - 1};
        std::uniform_int_distribution<std::size_t> anywhere(0, seed.size() - 1);
        for (int i = 0; i < 35; ++i) lengths.push_back(anywhere(random));
        for (std::size_t length : lengths) {
            tryVdb(folder_ / "case.vdb", seed.substr(0, length), "truncated to " + std::to_string(length), tally);
            ++cases;
        }
    }
    std::cout << cases << " truncated files, " << tally.errors << " errors\n";
    EXPECT_EQ(tally.errors, cases);
    EXPECT_EQ(tally.readable, 0);
    EXPECT_GE(cases, 150);
}

// 1 to 8 flipped bits, half of them in the first 1 KiB (header, grid table,
// metadata, transform, tree topology), half anywhere.
TEST_F(Robustness, BitFlippedVdbFilesEndInAnErrorOrAValidRead) {
    std::mt19937 random(8);
    Tally tally;
    int cases = 0;
    for (const std::string& seed : seedFiles(folder_)) {
        for (int i = 0; i < 80; ++i) {
            std::string bytes = seed;
            const std::size_t span = (i % 2 == 0) ? std::min<std::size_t>(1024, bytes.size()) : bytes.size();
            std::uniform_int_distribution<std::size_t> position(0, span - 1);
            const int flips = 1 + static_cast<int>(random() % 8);
            std::string label = "flipped";
            for (int f = 0; f < flips; ++f) {
                const std::size_t at = position(random);
                const int bit = static_cast<int>(random() % 8);
                bytes[at] = static_cast<char>(bytes[at] ^ (1 << bit));
                label += " " + std::to_string(at) + ":" + std::to_string(bit);
            }
            tryVdb(folder_ / "case.vdb", bytes, label, tally);
            ++cases;
        }
    }
    std::cout << cases << " bit-flipped files, " << tally.errors << " errors\n";
    EXPECT_EQ(tally.errors + tally.readable, cases);
    EXPECT_GE(tally.errors, 100) << tally.readable << " of " << cases << " still readable";
}

// Extreme values written over aligned 4- and 8-byte fields: counts, string
// lengths, offsets and chunk sizes become huge, negative or zero.
TEST_F(Robustness, HostileSizesInVdbFilesAreErrors) {
    std::mt19937 random(31337);
    const std::uint64_t extremes[] = {0xFFFFFFFFull, 0x7FFFFFFFull, 0x80000000ull, 0xFFFFFFFFFFFFFFFFull,
                                      0x8000000000000000ull, 0x7FFFFFFFFFFFFFFFull, 0x0ull, 0x10000000ull};
    Tally tally;
    int cases = 0;
    for (const std::string& seed : seedFiles(folder_)) {
        for (int i = 0; i < 50; ++i) {
            std::string bytes = seed;
            const std::size_t width = (i % 2) ? 8 : 4;
            const std::size_t span = (i % 4 < 2) ? std::min<std::size_t>(2048, bytes.size()) : bytes.size();
            const std::size_t at = (random() % (span - width)) & ~std::size_t{3};
            const std::uint64_t value = extremes[random() % std::size(extremes)];
            std::memcpy(bytes.data() + at, &value, width);
            tryVdb(folder_ / "case.vdb", bytes, "hostile " + std::to_string(value) + " at " + std::to_string(at), tally);
            ++cases;
        }
    }
    std::cout << cases << " hostile files, " << tally.errors << " errors\n";
    EXPECT_EQ(tally.errors + tally.readable, cases);
    EXPECT_GE(tally.errors, 80) << tally.readable << " of " << cases << " still readable";
}

// A valid scene with an export and a volume section, damaged as text (cut,
// bytes replaced) and as JSON (values swapped for wrong types and extremes).
TEST_F(Robustness, DamagedSceneFilesAreErrors) {
    writeAll(folder_ / "fluid_data_0001.vdb", seedFiles(folder_)[0]);
    const std::string valid = R"({
  "grid": {"resolution": [8, 8, 8], "bounds": {"min": [-0.1, -0.1, -0.1], "max": [0.1, 0.1, 0.1]}},
  "medium": {"index": 1.000273},
  "lights": [{"type": "spot", "position": [0, 1, 0], "direction": [0, -1, 0], "power": 2, "cone_angle_deg": 20}],
  "receivers": [{"type": "plane", "point": [0, -0.1, 0], "normal": [0, 1, 0], "size": 0.3}],
  "volume": {"path": "fluid_data_####.vdb", "grids": {"velocity": "velocity"}, "density_extinction": 2,
             "temperature_scale": 40},
  "export": {"vtk": {"fields": ["index", "temperature", "velocity"], "every": 2, "downsample": 2,
                     "region": {"min": [-0.05, -0.05, -0.05], "max": [0.05, 0.05, 0.05]}},
             "vdb": {"fields": ["density"]}}
})";
    const fs::path scenePath = folder_ / "scene.json";
    writeAll(scenePath, valid);
    ASSERT_NO_THROW(loadSceneFile(scenePath.string()));

    std::mt19937 random(99);
    int cases = 0, errors = 0;
    auto tryScene = [&](const std::string& text, const std::string& label) {
        writeAll(scenePath, text);
        ++cases;
        try {
            loadSceneFile(scenePath.string());
        } catch (const InputError& error) {
            EXPECT_NE(std::string(error.what()).find("scene.json"), std::string::npos) << label << ": " << error.what();
            ++errors;
        } catch (const std::exception& error) {
            ADD_FAILURE() << label << ": not an InputError: " << error.what();
        }
    };
    for (int i = 0; i < 40; ++i) {  // cut anywhere: never valid JSON
        const std::size_t length = random() % valid.size();
        tryScene(valid.substr(0, length), "cut at " + std::to_string(length));
    }
    const std::string junk = "{}[],:\"0-e.#\\\x01\xff";
    for (int i = 0; i < 40; ++i) {
        std::string text = valid;
        text[random() % text.size()] = junk[random() % junk.size()];
        tryScene(text, "replaced byte");
    }
    const nlohmann::json root = nlohmann::json::parse(valid);
    const std::vector<std::string> paths{"/volume/path", "/volume/grids/velocity", "/volume/density_extinction",
                                         "/volume/temperature_scale", "/export/vtk/fields/1", "/export/vtk/every",
                                         "/export/vtk/downsample", "/export/vtk/region/max", "/export/vdb/fields",
                                         "/grid/resolution/0", "/lights/0/cone_angle_deg", "/receivers/0/size"};
    const std::vector<nlohmann::json> hostile{nullptr, -1, 0, 1e308, -1e308, "", "####", "../../etc/passwd",
                                              nlohmann::json::array(), nlohmann::json::object(), true, 2.5,
                                              4294967296.0, "velocity"};
    for (const std::string& path : paths)
        for (const nlohmann::json& value : hostile) {
            nlohmann::json damaged = root;
            damaged[nlohmann::json::json_pointer(path)] = value;
            tryScene(damaged.dump(), path + " = " + value.dump());
        }
    std::cout << cases << " damaged scene files, " << errors << " errors\n";
    EXPECT_GE(errors, 150) << cases << " cases";
}

}  // namespace
}  // namespace eikon::io
