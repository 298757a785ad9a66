// Round trips to ParaView and Blender that used to fail silently, each
// tested from its failure: --vtk dropped --set export.vtk.*, `eikon paraview`
// took another scene's file, photon_direction was labelled unit "1", a
// simulated scene's delta_index was dense in the OpenVDB export, and a run
// stopped by a later frame's volume file left the frames before it behind.
#include "tests/integration/CliRun.h"
#include "tests/unit/VdbTestFiles.h"

#include <gtest/gtest.h>

#include <openvdb/openvdb.h>
#include <openvdb/io/File.h>

#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkStringArray.h>
#include <vtkXMLImageDataReader.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using eikon::test::Outcome;
using eikon::test::runEikon;

constexpr const char* kScene = eikon::test::kSmallSphereScene;

std::string readText(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

vtkSmartPointer<vtkImageData> readImage(const fs::path& path) {
    vtkNew<vtkXMLImageDataReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    return reader->GetOutput();
}

std::string unitOf(vtkImageData* image, const std::string& array) {
    auto* unit = vtkStringArray::SafeDownCast(image->GetFieldData()->GetAbstractArray((array + "_unit").c_str()));
    return unit ? unit->GetValue(0) : "(none)";
}

class RoundTrip : public eikon::test::CliFolderTest {
protected:
    RoundTrip() : CliFolderTest("eikon_roundtrip_") {}
    Outcome run(const std::string& scene, const std::string& arguments) const {
        return runEikon("run " + scene + " --out " + (dir_ / "out").string() + " --quiet " + arguments,
                        "LP_NUM_THREADS=2");
    }
};

// Before: --vtk replaced export.vtk with its defaults, so every frame and
// every field were written whatever --set said.
TEST_F(RoundTrip, VtkFlagKeepsTheExportSettingsOfSet) {
    const std::string scene = writeScene("scene.json", kScene);
    const Outcome outcome =
        run(scene, "--frames 3 --vtk --set export.vtk.every=2 --set 'export.vtk.fields=[\"delta_index\"]'");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    const fs::path vtk = dir_ / "out" / "vtk";
    EXPECT_TRUE(fs::exists(vtk / "fields_00000.vti"));
    EXPECT_FALSE(fs::exists(vtk / "fields_00001.vti")) << "export.vtk.every=2 was dropped";
    EXPECT_TRUE(fs::exists(vtk / "fields_00002.vti"));
    const auto image = readImage(vtk / "fields_00002.vti");
    EXPECT_NE(image->GetCellData()->GetArray("delta_index"), nullptr);
    EXPECT_EQ(image->GetCellData()->GetArray("index"), nullptr) << "export.vtk.fields was dropped";
}

// Before: photon_direction_unit was "1"; its values are Σ φ·d, W/m².
TEST_F(RoundTrip, PhotonDirectionIsInWattsPerSquareMetre) {
    const std::string scene = writeScene("scene.json", kScene);
    const Outcome outcome = run(scene, "--frames 1 --vtk --set 'export.vtk.fields=[\"fluence\", \"photon_direction\"]'");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    const auto image = readImage(dir_ / "out" / "vtk" / "fields_00000.vti");
    ASSERT_NE(image->GetCellData()->GetArray("photon_direction"), nullptr);
    EXPECT_EQ(unitOf(image, "photon_direction"), "W/m^2");
    EXPECT_EQ(unitOf(image, "fluence"), "W/m^2");
}

// Before: `eikon paraview DIR SCENE` wrote the state of any scene for any
// run. Now the run's journal holds its scene's fingerprint: the same scene
// with another camera is taken, another scene is refused and nothing written.
TEST_F(RoundTrip, ParaViewCommandRefusesAnotherScenesFile) {
    const std::string scene = writeScene("scene.json", kScene);
    ASSERT_EQ(run(scene, "--frames 1 --vtk").exitCode, 0);
    const fs::path out = dir_ / "out", state = out / "vtk" / "open_in_paraview.py";
    EXPECT_NE(readText(out / ".eikon-run").find("\nscene\t"), std::string::npos) << readText(out / ".eikon-run");

    fs::remove(state);
    const Outcome sameScene = runEikon("paraview " + out.string() + " " + scene + " --set camera.fov_deg=30");
    EXPECT_EQ(sameScene.exitCode, 0) << sameScene.output;
    EXPECT_TRUE(fs::exists(state));

    std::string other = kScene;
    other.replace(other.find("\"radius\": 0.2"), 13, "\"radius\": 0.3");
    const std::string otherScene = writeScene("other.json", other);
    fs::remove(state);
    for (const std::string& arguments : {otherScene, scene + " --set objects.0.radius=0.3"}) {
        const Outcome refused = runEikon("paraview " + out.string() + " " + arguments);
        EXPECT_EQ(refused.exitCode, 2) << refused.output;
        EXPECT_NE(refused.output.find("expected the scene the run in " + out.string() + " rendered"), std::string::npos)
            << refused.output;
        EXPECT_FALSE(fs::exists(state)) << arguments;
    }
}

// Before: a simulated scene's δn outside the plume is the ambient air's
// (2.7e-4 with n_ref = 1), not 0, so every voxel of delta_index stayed
// active. Now its background is the ambient δn (Gladstone–Dale,
// n − 1 = 2.93e-4 · 273.15 K / 293.15 K) and only the plume is active; the
// sparse grid reads back as the dense VTK export, cell by cell.
TEST_F(RoundTrip, SimulatedDeltaIndexIsSparseInTheOpenVdbExport) {
    const std::string scene = writeScene("plume.json", R"({
      "grid": {"resolution": [12, 12, 12], "bounds": {"min": [0, 0, 0], "max": [0.3, 0.3, 0.3]}},
      "lights": [{"type": "point", "position": [0.15, 1, 0.15], "power": 1}],
      "render": {"photons": 1024, "width": 16, "height": 12},
      "sim": {"resolution": [12, 12, 12],
              "sources": [{"type": "hot_plate", "min": [0.1, 0, 0.1], "max": [0.2, 0.03, 0.2], "temperature": 400}]},
      "export": {"vdb": {"fields": ["delta_index"]}, "vtk": {"fields": ["delta_index"]}}
    })");
    const Outcome outcome = run(scene, "--frames 2");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;

    openvdb::initialize();
    openvdb::io::File file((dir_ / "out" / "vdb" / "fields_00001.vdb").string());
    file.open();
    const auto grid = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("delta_index"));
    file.close();
    ASSERT_NE(grid, nullptr);
    const double ambient = 2.93e-4 * 273.15 / 293.15;
    EXPECT_NEAR(grid->background(), ambient, 1e-10);
    const std::size_t cells = 12 * 12 * 12;
    EXPECT_GT(grid->activeVoxelCount(), 0u) << "the plume";
    EXPECT_LT(grid->activeVoxelCount(), cells / 4) << "dense: the ambient air kept every voxel active";

    const auto image = readImage(dir_ / "out" / "vtk" / "fields_00001.vti");
    auto* dense = vtkFloatArray::SafeDownCast(image->GetCellData()->GetArray("delta_index"));
    ASSERT_NE(dense, nullptr);
    ASSERT_EQ(static_cast<std::size_t>(dense->GetNumberOfTuples()), cells);
    double largest = 0.0;
    for (vtkIdType c = 0; c < dense->GetNumberOfTuples(); ++c)
        largest = std::max(largest, std::abs(double(dense->GetValue(c)) - double(grid->background())));
    const auto accessor = grid->getConstAccessor();
    for (int k = 0; k < 12; ++k)
        for (int j = 0; j < 12; ++j)
            for (int i = 0; i < 12; ++i) {
                const float expected = dense->GetValue(i + 12 * (j + 12 * k));
                // Cells within 1e-6 of the largest distance from the background are background (VdbFrameWriter.h).
                ASSERT_NEAR(accessor.getValue(openvdb::Coord(i, j, k)), expected, 1e-6 * largest + 1e-12)
                    << i << ", " << j << ", " << k;
            }
}

// Before: a sequence whose third file holds non-finite values (found only
// when the file is sampled) stopped the run after frames 0 and 1 were
// written, and they stayed. Now what the run wrote goes with its journal,
// and a folder it made goes too; a folder that was there stays, empty.
TEST_F(RoundTrip, ARunStoppedByALaterFramesValuesLeavesNothing) {
    for (int f = 1; f <= 3; ++f) {
        char name[64];
        std::snprintf(name, sizeof name, "fluid_data_%04d.vdb", f);
        eikon::test::writeVdbFile(dir_ / name,
                                  {{"density", 1, [](double, double, double, int) { return 0.5f; }},
                                   {"temperature", 1, [f](double x, double y, double z, int) {
                                        return f == 3 && x > 0.3 && y > 0.3 && z > 0.3
                                                   ? std::numeric_limits<float>::quiet_NaN()
                                                   : float(f);
                                    }}},
                                  0.05, -0.6, 0.6);
    }
    std::string text = kScene;
    text.insert(text.rfind('}'), R"(, "volume": {"path": "fluid_data_####.vdb", "temperature_scale": 10,
        "density_extinction": 0.5}, "export": {"vdb": {}, "vtk": {}})");
    const std::string scene = writeScene("volume.json", text);
    const fs::path out = dir_ / "out";

    const Outcome outcome = run(scene, "--frames 3");
    EXPECT_EQ(outcome.exitCode, 2) << outcome.output;
    EXPECT_NE(outcome.output.find("fluid_data_0003.vdb"), std::string::npos) << outcome.output;
    EXPECT_NE(outcome.output.find("the frames this run wrote before are removed"), std::string::npos) << outcome.output;
    EXPECT_FALSE(fs::exists(out)) << "frames 0 and 1 were left behind";

    fs::create_directories(out);
    const Outcome again = run(scene, "--frames 3");
    EXPECT_EQ(again.exitCode, 2) << again.output;
    ASSERT_TRUE(fs::is_directory(out)) << "a folder the user made stays";
    EXPECT_TRUE(fs::is_empty(out)) << "something of the run stayed";

    EXPECT_EQ(run(scene, "--frames 2").exitCode, 0) << "the frames before the bad file render";
    EXPECT_TRUE(fs::exists(out / "frames" / "frame_00001.png"));
}

// Before: a volume reaching past the render grid was cut off without a
// word. Now the run says where its active voxels are, where the grid is,
// and how much of their box is cut off; a volume inside says nothing.
TEST_F(RoundTrip, AVolumePastTheGridIsReportedWithFigures) {
    const auto density = [](double, double, double, int) { return 0.5f; };
    // Voxels −4 … 4 of 0.125 m: whole voxels over −0.5625 … 0.5625 m.
    eikon::test::writeVdbFile(dir_ / "large.vdb", {{"density", 1, density}}, 0.125, -0.5, 0.5);
    eikon::test::writeVdbFile(dir_ / "small.vdb", {{"density", 1, density}}, 0.125, -0.25, 0.25);
    const auto sceneWith = [&](const std::string& name, const std::string& volume) {
        std::string text = kScene;
        text.insert(text.rfind('}'), ", \"volume\": " + volume);
        return writeScene(name + ".json", text);
    };
    const Outcome large = run(sceneWith("large", R"({"path": "large.vdb", "grids": {"temperature": ""}, "density_extinction": 0.5})"), "--frames 1");
    ASSERT_EQ(large.exitCode, 0) << large.output;
    EXPECT_NE(large.output.find("warning: "), std::string::npos) << large.output;
    EXPECT_NE(large.output.find("span x -0.5625 … 0.5625, y -0.5625 … 0.5625, z -0.5625 … 0.5625 m in the scene's "
                                "world, past the render grid's x -0.5 … 0.5, y 0 … 1, z -0.5 … 0.5 m"),
              std::string::npos)
        << large.output;
    // Inside: 1 × 0.5625 × 1 of 1.125³ m³.
    EXPECT_NE(large.output.find(": 60.5% of their box lies outside"), std::string::npos) << large.output;

    fs::remove_all(dir_ / "out");
    const Outcome small =
        run(sceneWith("small", R"({"path": "small.vdb", "grids": {"temperature": ""}, "density_extinction": 0.5, "offset": [0, 0.5, 0]})"),
            "--frames 1");
    ASSERT_EQ(small.exitCode, 0) << small.output;
    EXPECT_EQ(small.output.find("active voxels"), std::string::npos) << small.output;

    // grid.fit "volume" sizes the grid to the large volume: nothing is cut off.
    fs::remove_all(dir_ / "out");
    std::string fitted = kScene;
    const std::string bounds = R"(, "bounds": {"min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5]})";
    fitted.replace(fitted.find(bounds), bounds.size(), R"(, "fit": "volume")");
    fitted.insert(fitted.rfind('}'), R"(, "volume": {"path": "large.vdb", "grids": {"temperature": ""}, "density_extinction": 0.5})");
    const Outcome fit = run(writeScene("fit.json", fitted), "--frames 1");
    ASSERT_EQ(fit.exitCode, 0) << fit.output;
    EXPECT_EQ(fit.output.find("active voxels"), std::string::npos) << fit.output;
}

}  // namespace
