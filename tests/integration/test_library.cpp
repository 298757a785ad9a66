// The library (include/eikon/eikon.h), through its public header alone: a
// field handed in renders as the same field read from an OpenVDB file, bit
// for bit — image, radiance, receiver map and the report's photon figures;
// the fluence to the rounding of its float atomic sums — and every refused
// field leaves the renderer as it was.
#include "eikon/eikon.h"
#include "tests/unit/VdbTestFiles.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>

namespace {

namespace fs = std::filesystem;

// The render grid [0, 0.5]³ m in 32³ cells: h = 2⁻⁶ m, so the file's voxel
// (i, j, k) at (i, j, k)·h, placed half a voxel on, lands on the render
// cells' centres exactly.
constexpr int kCells = 32;
constexpr double kH = 0.5 / kCells;

std::string exact(double value) {
    std::ostringstream text;
    text.precision(17);
    text << value;
    return text.str();
}

// A lens-like bump of index over a hot core, a grey absorber and RGB
// scattering, as functions of the file's world position.
double bump(double x, double y, double z, double width) {
    const double r2 = (x - 0.25) * (x - 0.25) + (y - 0.25) * (y - 0.25) + (z - 0.25) * (z - 0.25);
    return std::exp(-r2 / (width * width));
}
float deltaIndexAt(double x, double y, double z) { return static_cast<float>(0.01 * bump(x, y, z, 0.08)); }
float temperatureAt(double x, double y, double z) { return static_cast<float>(300.0 * bump(x, y, z, 0.05)); }
float scatteringAt(double x, double y, double z, int c) {
    return static_cast<float>((0.5 + 0.25 * c) * bump(x, y, z, 0.1));
}
float extinctionAt(double x, double y, double z) { return static_cast<float>(2.0 * bump(x, y, z, 0.1)); }

// The scene; with `volumeFile`, its fields come from that file.
std::string sceneJson(const std::string& volumeFile) {
    std::string json = R"({
      "grid": {"bounds": {"min": [0, 0, 0], "max": [0.5, 0.5, 0.5]}, "resolution": [32, 32, 32]},
      "lights": [{"type": "directional", "direction": [0.1, -1, 0.05], "irradiance": [1, 1, 1]}],
      "receivers": [{"type": "plane", "point": [0.25, -0.05, 0.25], "normal": [0, 1, 0], "albedo": 0.8,
                     "size": 0.6, "resolution": 24}],
      "camera": {"position": [0.25, 0.6, 1.4], "target": [0.25, 0.1, 0.25], "fov_deg": 40},
      "render": {"width": 40, "height": 32, "photons": 20000, "seed": 3})";
    if (!volumeFile.empty()) {
        const std::string half = exact(0.5 * kH);
        json += R"(,
      "volume": {"path": ")" + volumeFile + R"(",
                 "grids": {"density": "", "temperature": "T", "delta_index": "dn", "extinction": "kappa",
                           "scattering": "sigma"},
                 "offset": [)" + half + ", " + half + ", " + half + "]}";
    }
    return json + "\n}";
}

struct Arrays {
    std::vector<float> deltaIndex, temperature, extinction, scattering;
};

Arrays arraysOnTheGrid() {
    Arrays a;
    for (int k = 0; k < kCells; ++k)
        for (int j = 0; j < kCells; ++j)
            for (int i = 0; i < kCells; ++i) {
                const double x = i * kH, y = j * kH, z = k * kH;  // the file's voxel position
                a.deltaIndex.push_back(deltaIndexAt(x, y, z));
                a.temperature.push_back(temperatureAt(x, y, z));
                a.extinction.push_back(extinctionAt(x, y, z));
                for (int c = 0; c < 3; ++c) a.scattering.push_back(scatteringAt(x, y, z, c));
            }
    return a;
}

eikon::Field field(const eikon::Renderer& renderer, const std::string& name, const std::vector<float>& values,
                   int channels = 1) {
    const eikon::Grid grid = renderer.grid();
    return {name,
            values.data(),
            {static_cast<std::size_t>(grid.cells[2]), static_cast<std::size_t>(grid.cells[1]),
             static_cast<std::size_t>(grid.cells[0])},
            channels,
            grid.boundsMin,
            grid.boundsMax};
}

std::vector<eikon::Field> allFields(const eikon::Renderer& renderer, const Arrays& a) {
    return {field(renderer, "delta_index", a.deltaIndex), field(renderer, "temperature", a.temperature),
            field(renderer, "extinction", a.extinction), field(renderer, "scattering", a.scattering, 3)};
}

// The report's figures that do not depend on the wall clock.
nlohmann::json figures(const std::string& report) {
    const nlohmann::json json = nlohmann::json::parse(report);
    return {{"photons", json.at("photons")}, {"host_bytes_copied", json.at("host_bytes_copied")},
            {"gpu_bytes_copied", json.at("gpu_bytes_copied")}};
}

// max |a − b| over max |b|.
double largestDifference(const std::vector<float>& a, const std::vector<float>& b) {
    EXPECT_EQ(a.size(), b.size());
    double difference = 0.0, largest = 0.0;
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
        difference = std::max(difference, std::abs(double(a[i]) - double(b[i])));
        largest = std::max(largest, std::abs(double(b[i])));
    }
    return difference / largest;
}

class Library : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        folder_ = fs::path(::testing::TempDir()) / "eikon_library";
        fs::create_directories(folder_);
        eikon::test::writeVdbFile(
            folder_ / "plume.vdb",
            {{"dn", 1, [](double x, double y, double z, int) { return deltaIndexAt(x, y, z); }},
             {"T", 1, [](double x, double y, double z, int) { return temperatureAt(x, y, z); }},
             {"kappa", 1, [](double x, double y, double z, int) { return extinctionAt(x, y, z); }},
             {"sigma", 3, [](double x, double y, double z, int c) { return scatteringAt(x, y, z, c); }}},
            kH, 0.0, 0.5 - 0.5 * kH);
    }
    static void TearDownTestSuite() { fs::remove_all(folder_); }
    static fs::path folder_;
};
fs::path Library::folder_;

TEST_F(Library, AFieldHandedInRendersAsTheSameFieldReadFromAVdbFile) {
    eikon::Renderer fromFile = eikon::Renderer::fromJson(sceneJson("plume.vdb"), folder_.string());
    fromFile.render();
    eikon::Renderer handed = eikon::Renderer::fromJson(sceneJson(""), folder_.string());
    const Arrays arrays = arraysOnTheGrid();
    handed.setFields(allFields(handed, arrays));
    handed.render();

    const eikon::ByteArray image = handed.image();
    ASSERT_EQ(image.shape, (std::vector<std::size_t>{32, 40, 3}));
    EXPECT_EQ(image.values, fromFile.image().values);
    EXPECT_EQ(handed.radiance().values, fromFile.radiance().values);
    ASSERT_EQ(handed.receiverCount(), 1u);
    const eikon::FloatArray map = handed.receiver(0);
    EXPECT_EQ(map.shape, (std::vector<std::size_t>{24, 24, 3}));
    EXPECT_EQ(map.values, fromFile.receiver(0).values);
    const eikon::FloatArray fluence = handed.fluence();
    EXPECT_EQ(fluence.shape, (std::vector<std::size_t>{32, 32, 32, 3}));
    // The photons' fluence tallies are float atomic sums, whose order varies
    // from run to run (shaders/common/fluence_deposits.glsl): the fluence
    // agrees to their rounding, as two renders of the same file do.
    eikon::Renderer again = eikon::Renderer::fromJson(sceneJson("plume.vdb"), folder_.string());
    again.render();
    const double handedVsFile = largestDifference(fluence.values, fromFile.fluence().values);
    const double runToRun = largestDifference(again.fluence().values, fromFile.fluence().values);
    std::cout << "fluence, largest difference over the largest value: handed vs file " << handedVsFile
              << ", file vs file " << runToRun << "\n";
    EXPECT_LT(handedVsFile, 1e-6) << "float32 sums of some thousand deposits a voxel";
    EXPECT_EQ(figures(handed.report()), figures(fromFile.report()));

    // Not a comparison of two empty frames: the receiver is lit, with a
    // caustic's contrast under the bump, and the volume holds light.
    double lo = std::numeric_limits<double>::max(), hi = 0.0, stored = 0.0;
    for (std::size_t t = 0; t < map.values.size(); t += 3) {
        lo = std::min(lo, double(map.values[t]));
        hi = std::max(hi, double(map.values[t]));
    }
    for (float v : fluence.values) stored += v;
    EXPECT_GT(lo, 0.1) << "W/m² of a 1 W/m² beam through thin absorption";
    EXPECT_GT(hi / lo, 1.2) << "the bump focuses or shadows part of the beam";
    EXPECT_GT(stored, 0.0);
    const nlohmann::json report = nlohmann::json::parse(handed.report());
    EXPECT_LT(std::abs(report.at("photons").at("energy_balance_error").get<double>()), 1e-3);
    EXPECT_EQ(report.at("caller_fields").at("host_bytes_copied").get<std::uint64_t>(),
              3u * 4u * kCells * kCells * kCells)
        << "only the grey extinction is copied, into three channels";
}

TEST_F(Library, TheNextFrameTakesOnlyTheFieldsThatChanged) {
    eikon::Renderer renderer = eikon::Renderer::fromJson(sceneJson(""), folder_.string());
    const Arrays arrays = arraysOnTheGrid();
    renderer.setFields(allFields(renderer, arrays));
    renderer.render();
    const std::vector<std::uint8_t> first = renderer.image().values;
    Arrays hotter = arrays;
    for (float& t : hotter.temperature) t *= 2.0f;
    renderer.setFields({field(renderer, "temperature", hotter.temperature),
                        field(renderer, "delta_index", arrays.deltaIndex), field(renderer, "extinction", arrays.extinction),
                        field(renderer, "scattering", arrays.scattering, 3)});
    renderer.render();
    EXPECT_NE(renderer.image().values, first) << "a hotter core bends the light more";
    const nlohmann::json report = nlohmann::json::parse(renderer.report());
    EXPECT_EQ(report.at("frame").get<int>(), 1);
}

// Each refusal: an eikon::Error naming the field and what was expected;
// the renderer renders its earlier fields afterwards, unchanged.
class LibraryRefusals : public Library {
protected:
    void SetUp() override {
        renderer_ = std::make_unique<eikon::Renderer>(eikon::Renderer::fromJson(sceneJson(""), folder_.string()));
        arrays_ = arraysOnTheGrid();
        renderer_->setFields(allFields(*renderer_, arrays_));
        renderer_->render();
        before_ = renderer_->image().values;
    }
    void expectRefused(const std::vector<eikon::Field>& fields, const std::vector<std::string>& words) {
        try {
            renderer_->setFields(fields);
            FAIL() << "accepted";
        } catch (const eikon::Error& error) {
            for (const std::string& word : words) EXPECT_NE(std::string(error.what()).find(word), std::string::npos)
                                                      << error.what() << " lacks " << word;
        }
        renderer_->render();
        EXPECT_EQ(renderer_->image().values, before_) << "the refused fields were not rendered";
    }
    std::unique_ptr<eikon::Renderer> renderer_;
    Arrays arrays_;
    std::vector<std::uint8_t> before_;
};

TEST_F(LibraryRefusals, AWrongShape) {
    eikon::Field wrong = field(*renderer_, "temperature", arrays_.temperature);
    wrong.shape = {16, 32, 64};
    expectRefused({wrong}, {"\"temperature\"", "(32, 32, 32)", "(16, 32, 64)"});
}

TEST_F(LibraryRefusals, ANaN) {
    std::vector<float> values = arrays_.deltaIndex;
    values[(5 * 32 + 4) * 32 + 3] = std::numeric_limits<float>::quiet_NaN();
    expectRefused({field(*renderer_, "delta_index", values)}, {"\"delta_index\"", "finite", "NaN", "(3, 4, 5)"});
}

TEST_F(LibraryRefusals, AGridThatIsNotTheScenes) {
    eikon::Field moved = field(*renderer_, "extinction", arrays_.extinction);
    moved.boundsMax = {0.5, 0.5, 0.75};
    expectRefused({moved}, {"\"extinction\"", "grid box", "0.75"});
}

TEST_F(LibraryRefusals, AWrongChannelCount) {
    expectRefused({field(*renderer_, "temperature", arrays_.scattering, 3)}, {"\"temperature\"", "1 channel", "3"});
}

TEST_F(LibraryRefusals, AnUnknownName) {
    expectRefused({field(*renderer_, "velocity", arrays_.temperature)}, {"\"velocity\"", "delta_index"});
}

TEST_F(LibraryRefusals, AnOutOfRangeValueFoundByTheOptics) {
    std::vector<float> negative = arrays_.extinction;
    negative[100] = -1.0f;
    expectRefused({field(*renderer_, "extinction", negative)}, {"extinction", ">= 0", "-1"});
}

TEST(LibraryScene, ASceneWithASolverIsRefused) {
    try {
        eikon::Renderer::fromJson(R"({"grid": {"bounds": {"min": [0,0,0], "max": [1,1,1]}, "resolution": [8,8,8]},
          "lights": [{"type": "directional", "direction": [0,-1,0], "irradiance": [1,1,1]}],
          "camera": {"position": [0.5,0.5,3], "target": [0.5,0.5,0.5], "fov_deg": 30},
          "sim": {"fluid": "air", "resolution": [8,8,8]}})");
        FAIL() << "accepted";
    } catch (const eikon::Error& error) {
        EXPECT_NE(std::string(error.what()).find("sim"), std::string::npos) << error.what();
    }
}

TEST(LibraryScene, BadSceneTextNamesTheKey) {
    try {
        eikon::Renderer::fromJson(R"({"grid": {"resolution": [8,8,-8]}})");
        FAIL() << "accepted";
    } catch (const eikon::Error& error) {
        EXPECT_NE(std::string(error.what()).find("scene (JSON text)"), std::string::npos) << error.what();
        EXPECT_NE(std::string(error.what()).find("expected"), std::string::npos) << error.what();
    }
}

}  // namespace
