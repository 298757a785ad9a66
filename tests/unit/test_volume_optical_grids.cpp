// Optical grids made in other tools, imported through `volume.grids`: an
// index grid (n) or a delta_index grid (n − n_ref) sets the index where the
// volume is, extinction and scattering grids (grey float or RGB vec3s) add
// to κ and σs, an anisotropy grid is the volume's g; values that cannot be
// are refused naming the scene file, the keys, the OpenVDB file and the
// position; a flame glows by Kirchhoff's law
// plus what an emission grid adds; and eikon's own export reads back
// as the fields it was written from.
#include "bridge/core/Error.h"
#include "io/export/ExportArrays.h"
#include "io/scene/SceneParser.h"
#include "io/vdb/VdbFrameWriter.h"
#include "sim/SceneFields.h"
#include "sim/optics/Blackbody.h"
#include "tests/unit/VdbTestFiles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

namespace eikon::sim {
namespace {

namespace fs = std::filesystem;
using test::VdbTestGrid;

class VolumeOpticalGrids : public ::testing::Test {
protected:
    void SetUp() override {
        folder_ = fs::path(::testing::TempDir()) /
                  ("eikon_optical_grids_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(folder_);
        fs::create_directories(folder_);
        // Linear in x, so trilinear sampling inside the active box is exact.
        const std::vector<VdbTestGrid> grids{
            {"n", 1, [](double x, double, double, int) { return float(1.2 + 0.1 * x); }},
            {"dn", 1, [](double x, double, double, int) { return float(0.01 * x); }},
            {"kappa", 3, [](double x, double, double, int c) { return float((c + 1) * (x + 0.5)); }},
            {"sigma", 1, [](double, double, double, int) { return 0.25f; }},
            {"too_much", 1, [](double, double, double, int) { return 10.0f; }},
            {"g", 1, [](double, double, double, int) { return 0.3f; }},
            {"flame", 1, [](double x, double, double, int) { return float(x + 0.5); }},
            {"glow", 1, [](double, double, double, int) { return 2.0f; }},
            {"negative_glow", 1, [](double, double, double, int) { return -1.0f; }}};
        test::writeVdbFile(folder_ / "lens.vdb", grids, 0.025, -0.3, 0.3);
    }
    void TearDown() override { fs::remove_all(folder_); }

    Scene scene(const std::string& volumeJson, const std::string& bounds = "[-0.2, -0.1, -0.1], \"max\": [0.2, 0.1, 0.1]") const {
        nlohmann::json root = nlohmann::json::parse(R"({
          "grid": {"resolution": [8, 4, 4], "bounds": {"min": )" + bounds + R"(}},
          "medium": {"index": 1.000273},
          "lights": [{"type": "point", "position": [0, 1, 0], "power": 1}]})");
        root["volume"] = nlohmann::json::parse(volumeJson);
        return parseScene(root, (folder_ / "scene.json").string());
    }
    std::string refusal(const std::string& volumeJson, const std::string& bounds) const {
        try {
            SceneFields fields(scene(volumeJson, bounds));
        } catch (const InputError& error) {
            return error.what();
        }
        return "no error";
    }
    fs::path folder_;
};

TEST_F(VolumeOpticalGrids, IndexExtinctionScatteringAndAnisotropyGridsAreTakenAsTheyAre) {
    SceneFields fields(scene(R"({"path": "lens.vdb", "grids": {"density": "", "temperature": "", "index": "n",
        "extinction": "kappa", "scattering": "sigma", "anisotropy": "g"}})"));
    const FieldSet& set = fields.fields();
    ASSERT_TRUE(set.hasExtinction());
    ASSERT_TRUE(set.hasScattering());
    ASSERT_TRUE(set.hasAnisotropy());
    for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 8; ++i) {
                const double x = set.grid.cellCentre(i, j, k).x;
                const std::size_t c = set.grid.linearIndex(i, j, k);
                // float32 n near 1.2: 1e-7 absolute.
                EXPECT_NEAR(set.deltaIndex[c], 1.2 + 0.1 * x - set.referenceIndex, 2e-7) << "n − n_ref";
                for (int ch = 0; ch < 3; ++ch) {
                    EXPECT_NEAR(set.extinction[3 * c + ch], (ch + 1) * (x + 0.5), 1e-6) << "RGB from a vec3s grid";
                    EXPECT_FLOAT_EQ(set.scattering[3 * c + ch], 0.25f) << "grey from a float grid";
                }
                EXPECT_FLOAT_EQ(set.anisotropy[c], 0.3f);
            }
}

TEST_F(VolumeOpticalGrids, ADeltaIndexGridAddsToTheTemperaturesChange) {
    SceneFields fields(scene(R"({"path": "lens.vdb", "grids": {"density": "", "temperature": "", "delta_index": "dn"}})"));
    const FieldSet& set = fields.fields();
    EXPECT_FALSE(set.hasExtinction());
    for (int i = 0; i < 8; ++i) {
        const std::size_t c = set.grid.linearIndex(i, 1, 2);
        EXPECT_FLOAT_EQ(set.deltaIndex[c], float(0.01 * set.grid.cellCentre(i, 1, 2).x));
    }
}

// Each refusal names the scene file, the `volume` keys the value came from,
// the OpenVDB file and the world position of the cell: cell 0 of the render
// grid is centred at (-0.175, -0.075, -0.075) m.
TEST_F(VolumeOpticalGrids, ImpossibleValuesAreRefusedNamingTheKeysTheFileAndThePosition) {
    const std::string inside = "[-0.2, -0.1, -0.1], \"max\": [0.2, 0.1, 0.1]";
    const std::string scene = (folder_ / "scene.json").string(), lens = (folder_ / "lens.vdb").string();
    // More scattering than extinction.
    EXPECT_EQ(refusal(R"({"path": "lens.vdb", "grids": {"density": "", "temperature": "", "extinction": "sigma",
        "scattering": "too_much"}})", inside),
              scene + ": volume.grids.scattering, medium.scattering, volume.grids.extinction, medium.extinction (the "
                      "scattering σs at (-0.175, -0.075, -0.075) m in " + lens + "): expected scattering <= extinction = "
                      "0.25 /m (the scattering grid's σs within the extinction it adds to), found 10 /m");
    // Past the active box an index grid reads its background, 0 here: no index.
    EXPECT_EQ(refusal(R"({"path": "lens.vdb", "grids": {"density": "", "temperature": "", "index": "n"}})",
                      "[-0.5, -0.1, -0.1], \"max\": [0.5, 0.1, 0.1]"),
              scene + ": volume.grids.index (grid \"n\" at (-0.4375, -0.075, -0.075) m in " + lens +
                  "): expected an index > 0 in the index grid (outside its active voxels a grid reads its background), "
                  "found 0");
    EXPECT_NE(refusal(R"({"path": "lens.vdb", "grids": {"density": "", "temperature": "", "index": "kappa"}})", inside)
                  .find(scene + ": volume.path: " + lens + ": grid \"kappa\": expected a float grid"),
              std::string::npos);
}

// Keys within their documented ranges that together make a value impossible
// are named with the file the values came from: a refractivity of 10 (> 0)
// turns the index negative where the temperature grid runs hot.
TEST_F(VolumeOpticalGrids, VolumeKeysThatMakeTheIndexImpossibleAreNamed) {
    const std::string message = refusal(R"({"path": "lens.vdb", "grids": {"density": "", "temperature": "flame"},
        "temperature_scale": 1000, "refractivity": 10})", "[-0.2, -0.1, -0.1], \"max\": [0.2, 0.1, 0.1]");
    EXPECT_EQ(message.rfind((folder_ / "scene.json").string() +
                                ": medium.index, volume.refractivity, volume.pressure, volume.reference_temperature (the "
                                "refractive index at (-0.175, -0.075, -0.075) m in " + (folder_ / "lens.vdb").string() +
                                "): expected a finite index n > 0",
                            0),
              0u)
        << message;
    EXPECT_NE(message.find("here at T = 618.15 K), found -3.89865"), std::string::npos) << message;
}

// Kirchhoff: a flame f = x + 0.5 at T = 293.15 K + 2000 K·f with soot κ = 3·f
// /m emits ε = scale·κ·B(T) per channel, plus an emission grid's 2 W/(m³·sr),
// to 2e-4 of the brightest channel (the Planck table's error and float32).
TEST_F(VolumeOpticalGrids, AFlameGlowsByKirchhoffsLawPlusTheEmissionGrid) {
    SceneFields fields(scene(R"({"path": "lens.vdb", "grids": {"density": "", "temperature": "", "flame": "flame",
        "emission": "glow"}, "flame_temperature": 2000, "flame_absorption": 3, "emission": "blackbody",
        "emission_scale": 0.5})"));
    const FieldSet& set = fields.fields();
    ASSERT_TRUE(set.hasEmission());
    ASSERT_TRUE(set.hasExtinction());
    for (int i = 0; i < 8; ++i) {
        const std::size_t c = set.grid.linearIndex(i, 2, 1);
        const double f = set.grid.cellCentre(i, 2, 1).x + 0.5;
        const glm::dvec3 planck = blackbodyRgb(293.15 + 2000.0 * f);
        const double brightest = std::max({planck.r, planck.g, planck.b});
        for (int ch = 0; ch < 3; ++ch) {
            EXPECT_NEAR(set.extinction[3 * c + ch], 3.0 * f, 1e-5) << "the soot absorbs, grey";
            EXPECT_NEAR(set.emission[3 * c + ch], 0.5 * 3.0 * f * planck[ch] + 2.0, 2e-4 * 1.5 * f * brightest + 1e-6)
                << "cell " << i << " channel " << ch;
        }
    }
    EXPECT_NE(refusal(R"({"path": "lens.vdb", "grids": {"density": "", "temperature": "", "emission": "negative_glow"}})",
                      "[-0.2, -0.1, -0.1], \"max\": [0.2, 0.1, 0.1]")
                  .find("volume.grids.emission (grid \"negative_glow\" at (-0.175, -0.075, -0.075) m in " +
                        (folder_ / "lens.vdb").string() + "): expected an emission >= 0 in the emission grid"),
              std::string::npos);
}

// A glowing volume's ε exported to OpenVDB (a vec3s `emission` grid) and
// imported again as grids.emission gives back the same ε, to 1e-6 of its
// largest value (the export's pruning tolerance).
TEST_F(VolumeOpticalGrids, ExportedEmissionReadsBackAsAnEmissionGrid) {
    const SceneFields glowing(scene(R"({"path": "lens.vdb", "grids": {"density": "", "temperature": "", "flame": "flame"},
        "flame_temperature": 2000, "flame_absorption": 3, "emission": "blackbody"})"));
    const FieldSet& source = glowing.fields();
    ASSERT_TRUE(source.hasEmission());
    io::VdbFrameWriter(folder_, "fields").writeFrame(0, 0.0, {source.grid, io::fieldArrays(viewsOf(source))});
    const SceneFields read(scene(R"({"path": "vdb/fields_00000.vdb", "grids": {"density": "", "temperature": "",
        "emission": "emission"}})"));
    const FieldSet& imported = read.fields();
    ASSERT_EQ(imported.emission.size(), source.emission.size());
    const float largest = *std::max_element(source.emission.begin(), source.emission.end());
    EXPECT_GT(largest, 100.0f) << "the flame glows";
    for (std::size_t k = 0; k < source.emission.size(); ++k)
        ASSERT_NEAR(imported.emission[k], source.emission[k], 1e-6 * largest) << "value " << k;
}

// eikon → OpenVDB → eikon: a glass sphere's index and an absorbing medium,
// exported and imported on the same grid, come back to 1e-12.
TEST_F(VolumeOpticalGrids, EikonsOwnExportReadsBackAsTheFieldsItWasWrittenFrom) {
    nlohmann::json root = nlohmann::json::parse(R"({
      "grid": {"resolution": [12, 10, 8], "bounds": {"min": [-0.3, -0.25, -0.2], "max": [0.3, 0.25, 0.2]}},
      "medium": {"index": 1.000273, "extinction": [0.5, 1, 2]},
      "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 0.15, "index": 1.5, "surface": "smooth"}],
      "lights": [{"type": "point", "position": [0, 1, 0], "power": 1}]})");
    const Scene original = parseScene(root, (folder_ / "original.json").string());
    const SceneFields written(original);
    const FieldSet& source = written.fields();
    io::VdbFrameWriter(folder_, "fields").writeFrame(0, 0.0, {source.grid, io::fieldArrays(viewsOf(source))});

    root.erase("objects");
    root["medium"] = {{"index", 1.000273}};
    root["volume"] = nlohmann::json::parse(R"({"path": "vdb/fields_00000.vdb", "grids": {"density": "", "temperature": "",
        "delta_index": "delta_index", "extinction": "extinction"}})");
    const SceneFields read(parseScene(root, (folder_ / "imported.json").string()));
    const FieldSet& imported = read.fields();
    ASSERT_EQ(imported.grid.resolution, source.grid.resolution);
    // The import samples trilinearly at the exported voxels' centres, whose
    // index-space coordinates carry the transform's rounding: 1e-12, not bits.
    ASSERT_EQ(imported.deltaIndex.size(), source.deltaIndex.size());
    ASSERT_EQ(imported.extinction.size(), source.extinction.size());
    for (std::size_t c = 0; c < source.deltaIndex.size(); ++c)
        ASSERT_NEAR(imported.deltaIndex[c], source.deltaIndex[c], 1e-12) << "cell " << c;
    for (std::size_t k = 0; k < source.extinction.size(); ++k)
        ASSERT_NEAR(imported.extinction[k], source.extinction[k], 1e-12) << "value " << k;
    EXPECT_GT(*std::max_element(source.deltaIndex.begin(), source.deltaIndex.end()), 0.4f) << "the sphere is there";
}

}  // namespace
}  // namespace eikon::sim
