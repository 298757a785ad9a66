// A gas mixture declared by its mass fractions (volume.fields.mass_fractions):
// n − 1 = ρ·[Σ Y_i·K_i + (1 − Σ Y_i)·K], K_i = (n0,i − 1)·R·T0/(p0·M_i) from
// the gases' refractivities at 0 °C and 1 atm and their molar masses
// (bridge/scene/GasSpecies.h), K the volume's gas (air's by default). A
// .vti of CO2 and hydrogen mixing into air, on the render cells' centres,
// must give that closed form in every cell, and an OpenVDB file's grids
// the same; mass fractions out of [0, 1],
// a mixture without a density and an unknown gas are refused by name.
#include "bridge/core/Error.h"
#include "bridge/scene/GasSpecies.h"
#include "io/scene/SceneParser.h"
#include "sim/SceneFields.h"
#include "sim/optics/AirOptics.h"
#include "tests/unit/VdbTestFiles.h"

#include <gtest/gtest.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataWriter.h>

#include <cmath>
#include <filesystem>
#include <functional>

namespace eikon::sim {
namespace {

namespace fs = std::filesystem;

constexpr int kN = 16;          // cells (and the file's points) per axis
constexpr double kH = 0.01;     // m
constexpr double kLow = -0.08;  // the grid's low corner, m

// The refractivities and molar masses the table states, and the ideal gas
// at 0 °C and 1 atm: the constants the mixture's optics must use.
double constantOf(double refractivity, double molarMass) {
    return refractivity * 8.314462618 * 273.15 / (101325.0 * molarMass);
}
const double kCo2 = constantOf(4.49e-4, 44.0095e-3);
const double kHydrogen = constantOf(1.32e-4, 2.01588e-3);

// The mixture at point (i, j, k): CO2 rising along x, hydrogen along y,
// the density of the mixture varying along z.
double co2At(int i, int, int) { return 0.6 * i / (kN - 1.0); }
double hydrogenAt(int, int j, int) { return 0.05 * j / (kN - 1.0); }
double densityAt(int, int, int k) { return 0.9 + 0.6 * k / (kN - 1.0); }

using Sample = std::function<double(int, int, int)>;

void writeMixture(const fs::path& path, const Sample& co2, const Sample& hydrogen) {
    vtkNew<vtkImageData> image;
    image->SetDimensions(kN, kN, kN);
    image->SetSpacing(kH, kH, kH);
    image->SetOrigin(kLow + 0.5 * kH, kLow + 0.5 * kH, kLow + 0.5 * kH);
    const std::pair<const char*, Sample> arrays[] = {{"rho", densityAt}, {"Y_CO2", co2}, {"Y_H2", hydrogen}};
    for (const auto& [name, sample] : arrays) {
        vtkNew<vtkFloatArray> array;
        array->SetName(name);
        for (int k = 0; k < kN; ++k)
            for (int j = 0; j < kN; ++j)
                for (int i = 0; i < kN; ++i) array->InsertNextValue(static_cast<float>(sample(i, j, k)));
        image->GetPointData()->AddArray(array);
    }
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetFileName(path.c_str());
    writer->SetInputData(image);
    ASSERT_EQ(writer->Write(), 1);
}

class VolumeMixture : public ::testing::Test {
protected:
    void SetUp() override {
        folder_ = fs::path(::testing::TempDir()) /
                  ("eikon_volume_mixture_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(folder_);
        fs::create_directories(folder_);
    }
    void TearDown() override { fs::remove_all(folder_); }

    Scene scene(const std::string& fields) const {
        nlohmann::json root = nlohmann::json::parse(R"({"grid": {"resolution": [16, 16, 16],
            "bounds": {"min": [-0.08, -0.08, -0.08], "max": [0.08, 0.08, 0.08]}},
            "medium": {"index": 1.000273},
            "lights": [{"type": "point", "position": [0, 1, 0], "power": 1}]})");
        root["volume"] = {{"path", "mixture.vti"}, {"fields", nlohmann::json::parse(fields)}};
        return parseScene(root, (folder_ / "scene.json").string());
    }

    // The refusal a scene's fields make, or "" where none.
    std::string refusal(const std::string& fields) const {
        try {
            SceneFields built(scene(fields));
        } catch (const InputError& error) {
            return error.what();
        }
        return "";
    }

    fs::path folder_;
};

constexpr const char* kMixtureFields =
    R"({"density": "rho", "mass_fractions": {"CO2": "Y_CO2", "H2": "Y_H2"}})";

TEST_F(VolumeMixture, IndexIsTheDensityTimesTheMassWeightedConstants) {
    writeMixture(folder_ / "mixture.vti", co2At, hydrogenAt);
    const Scene s = scene(kMixtureFields);
    SceneFields fields(s);
    const FieldSet& set = fields.fields();
    const GladstoneDale air;  // the volume's default gas, and its ambient state
    const double ambient = air.refractivityAt(293.15, 101325.0);
    const double medium = s.medium.index - set.referenceIndex;
    double error = 0.0, signal = 0.0;
    for (int k = 0; k < kN; ++k)
        for (int j = 0; j < kN; ++j)
            for (int i = 0; i < kN; ++i) {
                // float32 samples, as the file holds them
                const double y1 = static_cast<float>(co2At(i, j, k)), y2 = static_cast<float>(hydrogenAt(i, j, k));
                const double rho = static_cast<float>(densityAt(i, j, k));
                const double n1 = rho * (y1 * kCo2 + y2 * kHydrogen + (1.0 - y1 - y2) * air.airConstant());
                const double expected = medium + n1 - ambient;
                error = std::max(error, std::abs(set.deltaIndex[set.grid.linearIndex(i, j, k)] - expected));
                signal = std::max(signal, std::abs(n1 - rho * air.airConstant()));
            }
    // Hydrogen's K is 6.5 times air's (CO2's within 1% of it, per kilogram):
    // 5% hydrogen at 1.5 kg/m³ raises n − 1 by 9e-5 over the same density of air.
    EXPECT_GT(signal, 8e-5);
    EXPECT_LT(error / signal, 1e-5);  // float32 δn against a double closed form
    std::printf("[ measured ] mixture: largest |δn error| / largest change from the mixture = %.3g\n", error / signal);
}

// The same declaration reads an OpenVDB file's grids: density and hydrogen
// linear in x and y, which the grid's trilinear sampling keeps exact.
TEST_F(VolumeMixture, AnOpenVdbFileTakesTheSameDeclaration) {
    const auto rho = [](double x) { return 1.2 + 2.0 * x; };
    const auto hydrogen = [](double y) { return 0.05 + 0.25 * y; };
    test::writeVdbFile(folder_ / "mixture.vdb",
                       {{"rho", 1, [&](double x, double, double, int) { return static_cast<float>(rho(x)); }},
                        {"Y_H2", 1, [&](double, double y, double, int) { return static_cast<float>(hydrogen(y)); }}},
                       0.01, -0.1, 0.1);
    nlohmann::json root = nlohmann::json::parse(R"({"grid": {"resolution": [16, 16, 16],
        "bounds": {"min": [-0.08, -0.08, -0.08], "max": [0.08, 0.08, 0.08]}},
        "medium": {"index": 1.000273},
        "lights": [{"type": "point", "position": [0, 1, 0], "power": 1}],
        "volume": {"path": "mixture.vdb", "fields": {"density": "rho", "mass_fractions": {"H2": "Y_H2"}}}})");
    SceneFields fields(parseScene(root, (folder_ / "scene.json").string()));
    const FieldSet& set = fields.fields();
    const GladstoneDale air;
    const double medium = 1.000273 - set.referenceIndex, ambient = air.refractivityAt(293.15, 101325.0);
    double error = 0.0;
    for (int k = 0; k < kN; ++k)
        for (int j = 0; j < kN; ++j)
            for (int i = 0; i < kN; ++i) {
                const glm::dvec3 x = set.grid.cellCentre(i, j, k);
                const double y = hydrogen(x.y);
                const double expected = medium + rho(x.x) * (y * kHydrogen + (1.0 - y) * air.airConstant()) - ambient;
                error = std::max(error, std::abs(set.deltaIndex[set.grid.linearIndex(i, j, k)] - expected));
            }
    EXPECT_LT(error, 1e-9);  // of a δn change up to 1e-4 (float32 samples and δn)
}

// The table's air is the volume's default gas, so a mixture that is all
// "air" gives what a plain density does.
TEST_F(VolumeMixture, TheTablesAirIsTheDefaultGas) {
    const GasSpecies* air = findGasSpecies("air");
    ASSERT_NE(air, nullptr);
    EXPECT_NEAR(air->gladstoneDale(), GladstoneDale{}.airConstant(), 1e-4 * GladstoneDale{}.airConstant());
    EXPECT_NEAR(findGasSpecies("CO2")->gladstoneDale(), kCo2, 1e-15);
    EXPECT_EQ(findGasSpecies("co2"), nullptr);  // names as chemists write them
}

TEST_F(VolumeMixture, MassFractionsOutsideTheUnitIntervalAreRefused) {
    writeMixture(folder_ / "mixture.vti", [](int i, int, int) { return i == 3 ? 1.5 : 0.2; }, hydrogenAt);
    std::string message = refusal(kMixtureFields);
    EXPECT_NE(message.find("scene.json: volume.fields.mass_fractions.CO2 (array \"Y_CO2\" at (-0.045, "),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("expected a mass fraction in [0, 1] (to 0.001), found 1.5"), std::string::npos) << message;

    writeMixture(folder_ / "mixture.vti", [](int, int, int) { return 0.8; }, [](int, int, int) { return 0.3; });
    message = refusal(kMixtureFields);
    EXPECT_NE(message.find("scene.json: volume.fields.mass_fractions (the mass fractions' sum at "), std::string::npos)
        << message;
    EXPECT_NE(message.find("found 1.1"), std::string::npos) << message;
}

TEST_F(VolumeMixture, AMixtureNeedsADensityAndKnownGases) {
    writeMixture(folder_ / "mixture.vti", co2At, hydrogenAt);
    std::string message = refusal(R"({"temperature": "rho", "temperature_unit": "kelvin",
                                      "mass_fractions": {"CO2": "Y_CO2"}})");
    EXPECT_NE(message.find("scene.json: volume.fields.mass_fractions: expected no mass_fractions without a density "
                           "array"),
              std::string::npos)
        << message;
    message = refusal(R"({"density": "rho", "mass_fractions": {"Xe": "Y_Xe"}})");
    EXPECT_NE(message.find("scene.json: volume.fields.mass_fractions.Xe: expected one of the keys "), std::string::npos)
        << message;
    message = refusal(R"({"density": "rho", "mass_fractions": {"CO2": "Y_C02"}})");  // a zero for the O
    EXPECT_NE(message.find("expected a point or cell array \"Y_C02\" (volume.fields.mass_fractions.CO2), found the "
                           "arrays \"rho\", \"Y_CO2\", \"Y_H2\""),
              std::string::npos)
        << message;
}

}  // namespace
}  // namespace eikon::sim
