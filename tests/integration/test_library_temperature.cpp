// A temperature handed to the library with its unit declared
// (eikon::Field::unit) renders as the same temperature read from an OpenVDB
// file declared the same way (volume.fields.temperature_unit), bit for bit;
// an absolute temperature without a declared unit is refused with words
// that say how to declare it.
#include "eikon/eikon.h"
#include "tests/integration/LibraryRefusals.h"
#include "tests/unit/VdbTestFiles.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <sstream>

namespace {

namespace fs = std::filesystem;

// The render grid [0, 0.5]³ m in 32³ cells: h = 2⁻⁶ m, the file's voxel
// (i, j, k) at (i, j, k)·h, placed half a voxel on, lands on a cell centre.
constexpr int kCells = 32;
constexpr double kH = 0.5 / kCells;
constexpr double kAmbient = 293.15;  // K, volume.ambient_temperature's default

// A hot core 400 K over ambient, in kelvin and in Celsius, at the file's
// world position.
double heat(double x, double y, double z) {
    const double r2 = (x - 0.25) * (x - 0.25) + (y - 0.25) * (y - 0.25) + (z - 0.25) * (z - 0.25);
    return 400.0 * std::exp(-r2 / (0.06 * 0.06));
}
float kelvinAt(double x, double y, double z) { return static_cast<float>(kAmbient + heat(x, y, z)); }
float celsiusAt(double x, double y, double z) { return static_cast<float>(kAmbient - 273.15 + heat(x, y, z)); }

std::string exact(double value) {
    std::ostringstream text;
    text.precision(17);
    text << value;
    return text.str();
}

// The scene, looking at a checkerboard through the core; with `grid` and
// `unit`, its temperature comes from the file's grid of that name.
std::string sceneJson(const std::string& grid = "", const std::string& unit = "") {
    std::string json = R"({
      "grid": {"bounds": {"min": [0, 0, 0], "max": [0.5, 0.5, 0.5]}, "resolution": [32, 32, 32]},
      "lights": [{"type": "directional", "direction": [0.1, -1, 0.05], "irradiance": [1, 1, 1]}],
      "receivers": [{"type": "plane", "point": [0.25, -0.05, 0.25], "normal": [0, 1, 0], "albedo": 0.8,
                     "size": 0.6, "resolution": 24}],
      "camera": {"position": [0.25, 0.25, 3.0], "target": [0.25, 0.25, -4.0], "fov_deg": 8},
      "render": {"width": 48, "height": 48, "photons": 20000, "seed": 3,
                 "environment": {"type": "sky", "ground_height": -1.0, "checker_size": 0.01,
                                 "ground_a": [0.9, 0.9, 0.85], "ground_b": [0.05, 0.05, 0.06]}})";
    if (!grid.empty()) {
        const std::string half = exact(0.5 * kH);
        json += R"(,
      "volume": {"path": "hot.vdb", "fields": {"temperature": ")" + grid + R"(", "temperature_unit": ")" + unit +
                R"("}, "offset": [)" + half + ", " + half + ", " + half + "]}";
    }
    return json + "\n}";
}

std::vector<float> onTheGrid(float (*value)(double, double, double)) {
    std::vector<float> values;
    for (int k = 0; k < kCells; ++k)
        for (int j = 0; j < kCells; ++j)
            for (int i = 0; i < kCells; ++i) values.push_back(value(i * kH, j * kH, k * kH));
    return values;
}

eikon::Field temperature(const eikon::Renderer& renderer, const std::vector<float>& values, const std::string& unit) {
    const eikon::Grid grid = renderer.grid();
    return {"temperature", values.data(), {kCells, kCells, kCells}, 1, grid.boundsMin, grid.boundsMax, unit};
}

nlohmann::json photons(const eikon::Renderer& renderer) {
    return nlohmann::json::parse(renderer.report()).at("photons");
}

class LibraryTemperature : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        folder_ = fs::path(::testing::TempDir()) / "eikon_library_temperature";
        fs::create_directories(folder_);
        eikon::test::writeVdbFile(folder_ / "hot.vdb",
                                  {{"T", 1, [](double x, double y, double z, int) { return kelvinAt(x, y, z); }},
                                   {"Tc", 1, [](double x, double y, double z, int) { return celsiusAt(x, y, z); }}},
                                  kH, 0.0, 0.5 - 0.5 * kH);
    }
    static void TearDownTestSuite() { fs::remove_all(folder_); }

    // The file's frame and the handed frame, for one unit: bit for bit.
    static void expectAsTheFile(const std::string& grid, const std::string& unit,
                                float (*value)(double, double, double)) {
        eikon::Renderer fromFile = eikon::Renderer::fromJson(sceneJson(grid, unit), folder_.string());
        fromFile.render();
        eikon::Renderer handed = eikon::Renderer::fromJson(sceneJson(), folder_.string());
        const std::vector<float> values = onTheGrid(value);
        handed.setFields({temperature(handed, values, unit)});
        handed.render();
        EXPECT_EQ(handed.image().values, fromFile.image().values) << unit;
        EXPECT_EQ(handed.radiance().values, fromFile.radiance().values) << unit;
        EXPECT_EQ(handed.receiver(0).values, fromFile.receiver(0).values) << unit;
        EXPECT_EQ(photons(handed), photons(fromFile)) << unit;
        EXPECT_EQ(nlohmann::json::parse(handed.report()).at("caller_fields").at("host_bytes_copied"), 0);

        // Not two empty frames: the core bends the view of the checkerboard,
        // and the same values read in another unit give another frame.
        eikon::Renderer cold = eikon::Renderer::fromJson(sceneJson(), folder_.string());
        cold.render();
        EXPECT_NE(handed.image().values, cold.image().values) << "the hot core shifts the checkerboard";
        eikon::Renderer misread = eikon::Renderer::fromJson(sceneJson(), folder_.string());
        misread.setFields({temperature(misread, values, "kelvin_above_ambient")});
        misread.render();
        EXPECT_NE(misread.radiance().values, fromFile.radiance().values) << unit << " read as above ambient";
    }
    static fs::path folder_;
};
fs::path LibraryTemperature::folder_;

TEST_F(LibraryTemperature, KelvinRendersAsTheSameFileDeclaredKelvin) { expectAsTheFile("T", "kelvin", kelvinAt); }

TEST_F(LibraryTemperature, CelsiusRendersAsTheSameFileDeclaredCelsius) { expectAsTheFile("Tc", "celsius", celsiusAt); }

TEST_F(LibraryTemperature, AnAbsoluteTemperatureWithoutAUnitIsRefusedAndSaysHowToDeclareIt) {
    eikon::Renderer renderer = eikon::Renderer::fromJson(sceneJson(), folder_.string());
    const std::vector<float> kelvin = onTheGrid(kelvinAt);
    expectRefused(renderer, {temperature(renderer, kelvin, "")},
                  {"field \"temperature\"", "above ambient", "\"kelvin\"", "eikon::Field::unit", "temperature_unit=",
                   "293.15"});
}

TEST_F(LibraryTemperature, AnUnknownUnitOrAUnitOnAnotherFieldIsRefused) {
    eikon::Renderer renderer = eikon::Renderer::fromJson(sceneJson(), folder_.string());
    const std::vector<float> kelvin = onTheGrid(kelvinAt);
    expectRefused(renderer, {temperature(renderer, kelvin, "fahrenheit")},
                  {"\"temperature\"", "\"kelvin_above_ambient\"", "\"fahrenheit\""});
    eikon::Field density = temperature(renderer, kelvin, "kelvin");
    density.name = "density";
    expectRefused(renderer, {density}, {"\"density\"", "no unit", "\"kelvin\""});
}

TEST_F(LibraryTemperature, AScaleWithAnAbsoluteUnitIsRefused) {
    std::string json = sceneJson();
    json.insert(json.rfind('}'), R"(, "volume": {"path": "hot.vdb", "grids": {"density": "", "temperature": "Tc"},
                                                "temperature_scale": 2})");
    eikon::Renderer renderer = eikon::Renderer::fromJson(json, folder_.string());
    const std::vector<float> kelvin = onTheGrid(kelvinAt);
    expectRefused(renderer, {temperature(renderer, kelvin, "kelvin")}, {"\"temperature\"", "temperature_scale", "2"});
}

}  // namespace
