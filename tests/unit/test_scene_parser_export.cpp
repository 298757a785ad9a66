// The `export` and `volume` sections of scene files.
#include "io/scene/SceneParser.h"

#include "bridge/core/Error.h"
#include "io/scene/ExportParser.h"
#include "io/vdb/VolumeFramePath.h"
#include "tests/unit/SceneParserTestSupport.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace eikon {
namespace {

using namespace test;

json sceneWithExport(const json& exports) {
    json root = validScene();
    root["export"] = exports;
    return root;
}

TEST(SceneParserExport, DefaultsExportNothing) {
    const Scene scene = parseScene(validScene(), "test.json");
    EXPECT_FALSE(scene.exports.vtk.enabled);
    EXPECT_FALSE(scene.exports.vdb.enabled);
    EXPECT_FALSE(scene.volume.has_value());
}

TEST(SceneParserExport, ReadsEveryVtkKey) {
    const Scene scene = parseScene(sceneWithExport(json::parse(R"({"vtk": {
        "fields": ["index", "fluence", "extinction"], "every": 3, "downsample": 2, "compression": "lz4",
        "region": {"min": [-0.5, -0.5, -0.5], "max": [0.5, 0.25, 1]}}})")),
                                   "test.json");
    const VtkExportDesc& vtk = scene.exports.vtk;
    EXPECT_TRUE(vtk.enabled);
    EXPECT_EQ(vtk.fields, (std::vector<std::string>{"index", "fluence", "extinction"}));
    EXPECT_EQ(vtk.every, 3);
    EXPECT_EQ(vtk.downsample, 2);
    EXPECT_EQ(vtk.compression, VtkExportDesc::Compression::Lz4);
    ASSERT_TRUE(vtk.region.has_value());
    EXPECT_EQ(vtk.region->max, glm::dvec3(0.5, 0.25, 1));
    EXPECT_TRUE(vtk.exportsFrame(0));
    EXPECT_FALSE(vtk.exportsFrame(2));
    EXPECT_TRUE(vtk.exportsFrame(6));
    EXPECT_TRUE(vtk.wants("fluence"));
    EXPECT_FALSE(vtk.wants("scattering"));
    // Exporting fluence needs it stored, whether or not the medium scatters.
    EXPECT_TRUE(scene.tracer.storeFluence);
}

TEST(SceneParserExport, EmptySectionExportsEveryField) {
    const Scene scene = parseScene(sceneWithExport(json::parse(R"({"vtk": {}, "vdb": {"every": 2}})")), "test.json");
    EXPECT_TRUE(scene.exports.vtk.enabled);
    EXPECT_TRUE(scene.exports.vtk.fields.empty());
    EXPECT_EQ(scene.exports.vtk.compression, VtkExportDesc::Compression::Zlib);
    EXPECT_TRUE(scene.exports.vdb.enabled);
    EXPECT_EQ(scene.exports.vdb.every, 2);
    EXPECT_EQ(scene.exports.vdb.upAxis, VdbExportDesc::UpAxis::Y);
    EXPECT_EQ(parseScene(sceneWithExport(json::parse(R"({"vdb": {"up_axis": "z"}})")), "test.json").exports.vdb.upAxis,
              VdbExportDesc::UpAxis::Z);
    EXPECT_FALSE(scene.tracer.storeFluence);
    EXPECT_FALSE(parseScene(sceneWithExport(json::parse(R"({"vtk": {"enabled": false}})")), "test.json")
                     .exports.vtk.enabled);
}

TEST(SceneParserExport, BadValuesAreReportedAtTheirPath) {
    expectErrorAt(sceneWithExport(json::parse(R"({"paraview": {}})")), "export.paraview", "unknown key");
    expectErrorAt(sceneWithExport(json::parse(R"({"vtk": {"fields": ["index", "n"]}})")), "export.vtk.fields[1]",
                  "one of \"index\"");
    expectErrorAt(sceneWithExport(json::parse(R"({"vtk": {"fields": ["index", "index"]}})")),
                  "export.vtk.fields[1]", "each field listed once");
    expectErrorAt(sceneWithExport(json::parse(R"({"vtk": {"fields": []}})")), "export.vtk.fields", "non-empty");
    expectErrorAt(sceneWithExport(json::parse(R"({"vtk": {"every": 0}})")), "export.vtk.every", "integer in [1,");
    expectErrorAt(sceneWithExport(json::parse(R"({"vtk": {"downsample": 1.5}})")), "export.vtk.downsample", "integer");
    expectErrorAt(sceneWithExport(json::parse(R"({"vtk": {"compression": "gzip"}})")), "export.vtk.compression",
                  "one of \"zlib\", \"lz4\", \"none\"");
    expectErrorAt(sceneWithExport(json::parse(R"({"vdb": {"compression": "zlib"}})")), "export.vdb.compression",
                  "unknown key");
    expectErrorAt(sceneWithExport(json::parse(R"({"vdb": {"up_axis": "x"}})")), "export.vdb.up_axis",
                  "one of \"y\", \"z\"");
    expectErrorAt(sceneWithExport(json::parse(R"({"vtk": {"region": {"min": [0, 0, 0], "max": [1, 0, 1]}}})")),
                  "export.vtk.region.max[1]", "must not be empty");
    // The grid spans [-1, 1] × [-0.5, 0.5] × [-2, 2].
    expectErrorAt(sceneWithExport(json::parse(R"({"vtk": {"region": {"min": [5, 0, 0], "max": [6, 1, 1]}}})")),
                  "export.vtk.region", "at least one cell centre");
    expectErrorAt(sceneWithExport(json::parse(R"({"vtk": {"fields": ["velocity"]}})")), "export.vtk.fields[0]",
                  "needs a `sim` section");
    expectErrorAt(sceneWithExport(json::parse(R"({"vdb": {"fields": ["index", "density"]}})")),
                  "export.vdb.fields[1]", "needs a `sim` section or a `volume` grid");
}

TEST(SceneParserExport, ReceiversAndPhotonPaths) {
    const Scene defaults = parseScene(sceneWithExport(json::parse(R"({"vtk": {}})")), "test.json");
    EXPECT_TRUE(defaults.exports.vtk.receivers);
    EXPECT_EQ(defaults.exports.vtk.photonPaths, 0);
    const Scene scene = parseScene(
        sceneWithExport(json::parse(R"({"vtk": {"receivers": false, "photon_paths": 500, "path_vertices": 64}})")),
        "test.json");
    EXPECT_FALSE(scene.exports.vtk.receivers);
    EXPECT_EQ(scene.exports.vtk.photonPaths, 500);
    EXPECT_EQ(scene.exports.vtk.pathVertices, 64);
    expectErrorAt(sceneWithExport(json::parse(R"({"vtk": {"path_vertices": 1}})")), "export.vtk.path_vertices",
                  "integer in [2, 4096]");
    expectErrorAt(sceneWithExport(json::parse(R"({"vtk": {"photon_paths": 100000, "path_vertices": 4096}})")),
                  "export.vtk.photon_paths", "photon_paths × path_vertices <= 4194304");
    expectErrorAt(sceneWithExport(json::parse(R"({"vdb": {"photon_paths": 5}})")), "export.vdb.photon_paths",
                  "unknown key");
}

TEST(SceneParserExport, SimFieldsCanBeExportedWithASim) {
    json root = sceneWithExport(json::parse(R"({"vtk": {"fields": ["velocity", "temperature", "dye"]}})"));
    root["sim"] = json::object();
    EXPECT_EQ(parseScene(root, "test.json").exports.vtk.fields.size(), 3u);
}

class SceneParserVolume : public ::testing::Test {
protected:
    void SetUp() override {
        folder_ = std::filesystem::path(::testing::TempDir()) /  // one per test: ctest runs tests in parallel
                  ("eikon_volume_parse_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        std::filesystem::create_directories(folder_);
        std::ofstream(folder_ / "fluid_data_0007.vdb") << "not read by the parser";
        std::ofstream(folder_ / "single.vdb") << "not read by the parser";
    }
    Scene parse(const json& volume) {
        json root = validScene();
        root["volume"] = volume;
        return parseScene(root, (folder_ / "scene.json").string());
    }
    std::string error(const json& volume) {
        try {
            parse(volume);
        } catch (const InputError& e) {
            return e.what();
        }
        ADD_FAILURE() << "accepted " << volume.dump();
        return "";
    }
    void TearDown() override { std::filesystem::remove_all(folder_); }
    std::filesystem::path folder_;
};

TEST_F(SceneParserVolume, ReadsASequenceWithGridNamesAndOptics) {
    const Scene scene = parse(json::parse(R"({"path": "fluid_data_####.vdb", "frame_start": 7, "frame_time": 0.04,
        "grids": {"density": "smoke density", "temperature": "heat", "flame": "flame", "velocity": "vel"},
        "offset": [0, -1, 0], "density_extinction": [2, 3, 4], "density_scattering": 1, "anisotropy": 0.3,
        "ambient_temperature": 300, "temperature_scale": 50, "flame_temperature": 800})"));
    ASSERT_TRUE(scene.volume.has_value());
    const VolumeDesc& v = *scene.volume;
    EXPECT_TRUE(v.sequence);
    EXPECT_EQ(v.frameStart, 7);
    EXPECT_EQ(v.densityGrid, "smoke density");
    EXPECT_EQ(v.velocityGrid, "vel");
    EXPECT_EQ(v.densityExtinction, glm::dvec3(2, 3, 4));
    EXPECT_EQ(v.temperatureScale, 50.0);
    EXPECT_EQ(volumeFramePath(v, 7), (folder_ / "fluid_data_0007.vdb").string());
    EXPECT_EQ(volumeFramePath(v, 12345), (folder_ / "fluid_data_12345.vdb").string());
}

TEST_F(SceneParserVolume, ASingleFileIsNotASequence) {
    const Scene scene = parse(json::parse(R"({"path": "single.vdb"})"));
    EXPECT_FALSE(scene.volume->sequence);
    EXPECT_EQ(volumeFramePath(*scene.volume, 3), (folder_ / "single.vdb").string());
    EXPECT_EQ(scene.volume->densityGrid, "density");
    EXPECT_EQ(scene.volume->temperatureGrid, "temperature");
}

TEST_F(SceneParserVolume, BadValuesAreReportedAtTheirPath) {
    EXPECT_NE(error(json::parse(R"({"path": "fluid_data_####.vdb"})")).find("volume.path: expected an existing .vdb file for frame_start"),
              std::string::npos);
    EXPECT_NE(error(json::parse(R"({"path": "missing.vdb"})")).find("missing.vdb\", which does not exist"),
              std::string::npos);
    EXPECT_NE(error(json::parse(R"({"path": "a_##_##.vdb"})")).find("at most one run of '#'"), std::string::npos);
    EXPECT_NE(error(json::parse(R"({"path": "single.vdb", "density_extinction": 1, "density_scattering": 2})"))
                  .find("volume.density_scattering: expected density_scattering <= density_extinction"),
              std::string::npos);
    EXPECT_NE(error(json::parse(R"({"path": "single.vdb", "grids": {"density": "", "temperature": ""}})"))
                  .find("volume.grids: expected at least one grid named"),
              std::string::npos);
    EXPECT_NE(error(json::parse(R"({"path": "single.vdb", "grids": {"index": "n", "delta_index": "dn"}})"))
                  .find("volume.grids.delta_index: expected \"\" when `index` names a grid"),
              std::string::npos);
    EXPECT_NE(error(json::parse(R"({"path": "single.vdb", "anisotropy": 0.5, "grids": {"anisotropy": "g"}})"))
                  .find("volume.anisotropy: expected no value when grids.anisotropy names a grid"),
              std::string::npos);
    EXPECT_NE(error(json::parse(R"({"path": "single.vdb", "grids": {"vel": "v"}})")).find("volume.grids.vel"),
              std::string::npos);
    EXPECT_NE(error(json::parse(R"({"path": "single.vdb", "preset": "blender"})")).find("volume.blender_domain"),
              std::string::npos);
    EXPECT_NE(error(json::parse(R"({"path": "single.vdb", "preset": "blender", "transform": {"scale": 2},
                                    "blender_domain": {"location": [0, 0, 0], "dimensions": [1, 1, 1]}})"))
                  .find("volume.transform: expected no `transform` with preset \"blender\""),
              std::string::npos);
    EXPECT_NE(error(json::parse(R"({"path": "single.vdb", "blender_domain": {"location": [0, 0, 0], "dimensions": [1, 1, 1]}})"))
                  .find("volume.blender_domain: expected no `blender_domain` without preset \"blender\""),
              std::string::npos);
    EXPECT_NE(error(json::parse(R"({"path": "single.vdb", "preset": "blender",
                                    "blender_domain": {"location": [0, 0, 0], "dimensions": [1, 0, 1]}})"))
                  .find("volume.blender_domain.dimensions"),
              std::string::npos);
    EXPECT_NE(error(json::parse(R"({"path": "single.vdb", "preset": "maya"})")).find("volume.preset"),
              std::string::npos);
    json both = validScene();
    both["sim"] = json::object();
    both["volume"] = {{"path", "single.vdb"}};
    try {
        parseScene(both, (folder_ / "scene.json").string());
        ADD_FAILURE() << "sim and volume accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("volume: expected either a sim section or a volume"), std::string::npos)
            << e.what();
    }
}

TEST_F(SceneParserVolume, ReadsEmissionAndRefusesWhatCouldNotGlow) {
    const Scene scene = parse(json::parse(R"({"path": "single.vdb", "grids": {"flame": "flame", "emission": "glow"},
        "flame_absorption": 4, "emission": "blackbody", "emission_scale": 0.5, "emission_lights": true})"));
    const VolumeDesc& v = *scene.volume;
    EXPECT_EQ(v.emission, VolumeDesc::Emission::Blackbody);
    EXPECT_EQ(v.emissionScale, 0.5);
    EXPECT_EQ(v.flameAbsorption, 4.0);
    EXPECT_EQ(v.emissionGrid, "glow");
    EXPECT_TRUE(v.emissionLights);
    EXPECT_EQ(parse(json::parse(R"({"path": "single.vdb"})")).volume->emission, VolumeDesc::Emission::None);

    EXPECT_NE(error(json::parse(R"({"path": "single.vdb", "flame_absorption": 2})"))
                  .find("volume.flame_absorption: expected no flame_absorption without a flame grid"),
              std::string::npos);
    EXPECT_NE(error(json::parse(R"({"path": "single.vdb", "emission_scale": 2})"))
                  .find("volume.emission_scale: expected no emission_scale without emission \"blackbody\""),
              std::string::npos);
    EXPECT_NE(error(json::parse(R"({"path": "single.vdb", "emission": "glow"})")).find("volume.emission: expected one of"),
              std::string::npos);
    EXPECT_NE(error(json::parse(R"({"path": "single.vdb", "grids": {"temperature": "", "density": "", "extinction": "k"},
                                    "emission": "blackbody"})"))
                  .find("volume.emission: expected a temperature or flame grid"),
              std::string::npos);
    EXPECT_NE(error(json::parse(R"({"path": "single.vdb", "emission": "blackbody"})"))
                  .find("volume.emission: expected something that absorbs"),
              std::string::npos);
    EXPECT_NE(error(json::parse(R"({"path": "single.vdb", "emission_lights": true})"))
                  .find("volume.emission_lights: expected no emission_lights without emission"),
              std::string::npos);
    json wavefront = validScene();
    wavefront["tracer"] = {{"estimator", "wavefront"}};
    wavefront["volume"] = json::parse(R"({"path": "single.vdb", "grids": {"emission": "glow"}, "emission_lights": true})");
    try {
        parseScene(wavefront, (folder_ / "scene.json").string());
        ADD_FAILURE() << "emission lights with the wavefront accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("volume.emission_lights: expected false with tracer.estimator \"wavefront\""),
                  std::string::npos)
            << e.what();
    }
    json dark = validScene();
    dark["lights"] = json::array();
    dark["volume"] = json::parse(R"({"path": "single.vdb", "grids": {"emission": "glow"}, "emission_lights": true})");
    EXPECT_TRUE(parseScene(dark, (folder_ / "scene.json").string()).lights.empty()) << "the fire is the only light";
    dark["volume"]["emission_lights"] = false;
    EXPECT_THROW(parseScene(dark, (folder_ / "scene.json").string()), InputError);
}

}  // namespace
}  // namespace eikon
