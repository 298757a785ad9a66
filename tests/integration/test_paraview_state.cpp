// The ParaView state a run with VTK export writes (io/vtk/ParaViewState):
// valid Python that opens only collections that exist, with the scene's
// camera; and, where ParaView's pvbatch and its Python modules can be run
// (EIKON_PVBATCH names the executable; python3-paraview conflicts with
// libvtk9-dev on Debian 12, docs/paraview.md), a picture that shows the
// fields, receivers and paths.
#include "io/image/ImageIo.h"
#include "io/vtk/ParaViewState.h"
#include "tests/integration/CliRun.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using eikon::test::runEikon;

constexpr const char* kScene = R"({
  "grid": {"resolution": [16, 16, 16], "bounds": {"min": [-0.5, 0, -0.5], "max": [0.5, 1, 0.5]}},
  "medium": {"index": 1.0, "extinction": [0.2, 0.2, 0.2], "scattering": [0.1, 0.1, 0.1]},
  "objects": [{"type": "sphere", "center": [0, 0.5, 0], "radius": 0.2, "index": 1.5}],
  "lights": [{"type": "point", "position": [0, 1.5, 0], "power": [10, 10, 10]}],
  "receivers": [{"type": "plane", "point": [0, 0.05, 0], "normal": [0, 1, 0], "size": 1.0, "resolution": 32}],
  "camera": {"position": [0, 1, 2.5], "target": [0, 0.4, 0], "up": [0, 1, 0], "fov_deg": 45},
  "render": {"photons": 4096, "width": 32, "height": 24, "seed": 3},
  "export": {"vtk": {"photon_paths": 50}}
})";

class ParaViewState : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("eikon_pv_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    fs::path runScene() {
        std::ofstream(dir_ / "scene.json") << kScene;
        const auto outcome = runEikon("run " + (dir_ / "scene.json").string() + " --out " + (dir_ / "out").string() +
                                      " --frames 2 --quiet");
        EXPECT_EQ(outcome.exitCode, 0) << outcome.output;
        return dir_ / "out" / "vtk" / "open_in_paraview.py";
    }
    fs::path dir_;
};

std::string readText(const fs::path& path) {
    std::ifstream file(path);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

std::set<std::string> openedCollections(const std::string& script) {
    std::set<std::string> names;
    const std::regex call(R"(collection\('(\w+)'\))");
    for (auto it = std::sregex_iterator(script.begin(), script.end(), call); it != std::sregex_iterator(); ++it)
        names.insert((*it)[1]);
    return names;
}

TEST_F(ParaViewState, RunWritesValidPythonThatOpensOnlyWhatExists) {
    const fs::path script = runScene();
    ASSERT_TRUE(fs::exists(script));
    const std::string text = readText(script);
    // The scene has no meshes: no meshes collection, so none is opened.
    EXPECT_EQ(openedCollections(text), (std::set<std::string>{"fields", "receivers", "photon_paths"}));
    for (const std::string& name : openedCollections(text))
        EXPECT_TRUE(fs::exists(script.parent_path() / (name + ".pvd"))) << name;
    EXPECT_NE(text.find("camera_position = [0, 1, 2.5]"), std::string::npos);
    EXPECT_NE(text.find("camera_target = [0, 0.40000000000000002, 0]"), std::string::npos);
    EXPECT_NE(text.find("slice_normal = [0, 0, 1]"), std::string::npos);  // the camera looks along −z mostly
    // paraview.simple resets the camera on a script's first Render(): one
    // comes before the camera is set (pvbatch checks it, below, where it can).
    EXPECT_LT(text.find("Render(view)"), text.find("view.CameraPosition = camera_position"));
    const std::string parse = "python3 -c \"import ast, sys; ast.parse(open(sys.argv[1]).read())\" " + script.string();
    EXPECT_EQ(std::system(parse.c_str()), 0) << text;
}

TEST_F(ParaViewState, CollectionsWithoutAnIndexAreLeftOut) {
    std::ofstream(dir_ / "fields.pvd") << "<VTKFile/>";
    eikon::io::ParaViewState state;
    eikon::io::writeParaViewState(dir_, state);
    EXPECT_EQ(openedCollections(readText(dir_ / "open_in_paraview.py")), (std::set<std::string>{"fields"}));
    EXPECT_EQ(readText(dir_ / "open_in_paraview.py").find("fields_static"), std::string::npos) << "no such file here";
}

// A gas heated by a plate: concentration and dye never change, so they are
// written once into fields_static.vti and the state merges that file into
// the fields; every frame holds the rest.
TEST_F(ParaViewState, ArraysARunNeverChangesAreWrittenOnceAndMerged) {
    std::ofstream(dir_ / "plume.json") << R"({
      "grid": {"resolution": [12, 12, 12], "bounds": {"min": [0, 0, 0], "max": [0.3, 0.3, 0.3]}},
      "lights": [{"type": "point", "position": [0.15, 1, 0.15], "power": 1}],
      "render": {"photons": 1024, "width": 16, "height": 12},
      "sim": {"resolution": [12, 12, 12],
              "sources": [{"type": "hot_plate", "min": [0.1, 0, 0.1], "max": [0.2, 0.03, 0.2], "temperature": 400}]}
    })";
    const auto outcome = runEikon("run " + (dir_ / "plume.json").string() + " --out " + (dir_ / "out").string() +
                                  " --frames 3 --vtk --quiet");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    const fs::path vtk = dir_ / "out" / "vtk";
    ASSERT_TRUE(fs::exists(vtk / "fields_static.vti"));
    const std::string once = readText(vtk / "fields_static.vti");
    EXPECT_NE(once.find("Name=\"dye\""), std::string::npos);
    EXPECT_NE(once.find("Name=\"concentration\""), std::string::npos);
    EXPECT_EQ(once.find("Name=\"temperature\""), std::string::npos);
    for (const char* frame : {"fields_00000.vti", "fields_00002.vti"}) {
        const std::string text = readText(vtk / frame);
        EXPECT_EQ(text.find("Name=\"dye\""), std::string::npos) << frame;
        EXPECT_NE(text.find("Name=\"temperature\""), std::string::npos) << frame;
    }
    const std::string script = readText(vtk / "open_in_paraview.py");
    EXPECT_NE(script.find("AppendAttributes"), std::string::npos);
    EXPECT_NE(script.find("'fields_static.vti'"), std::string::npos);
}

// `eikon paraview DIR SCENE` writes the state again, with the scene's camera
// as --set leaves it; a folder without a VTK export is refused (exit 2) and
// gets nothing.
TEST_F(ParaViewState, TheParaViewCommandRewritesTheState) {
    const fs::path script = runScene();
    fs::remove(script);
    const fs::path scene = dir_ / "scene.json";
    const auto outcome =
        runEikon("paraview " + (dir_ / "out").string() + " " + scene.string() + " --set camera.fov_deg=30");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    ASSERT_TRUE(fs::exists(script));
    const std::string text = readText(script);
    EXPECT_NE(text.find("camera_fov_deg = 30"), std::string::npos);
    EXPECT_EQ(openedCollections(text), (std::set<std::string>{"fields", "receivers", "photon_paths"}));

    fs::create_directories(dir_ / "empty");
    const auto refused = runEikon("paraview " + (dir_ / "empty").string() + " " + scene.string());
    EXPECT_EQ(refused.exitCode, 2) << refused.output;
    EXPECT_NE(refused.output.find("no vtk/ folder"), std::string::npos) << refused.output;
    EXPECT_TRUE(fs::is_empty(dir_ / "empty"));
}

// Where pvbatch is available: after the state has run, ParaView's view has
// the scene's camera — not the one paraview.simple's first Render() resets
// to the data, which replaced it before.
TEST_F(ParaViewState, PvbatchKeepsTheScenesCamera) {
    const char* pvbatch = std::getenv("EIKON_PVBATCH");
    if (!pvbatch) GTEST_SKIP() << "EIKON_PVBATCH does not name ParaView's pvbatch (docs/paraview.md)";
    const fs::path script = runScene();
    std::ofstream(dir_ / "camera.py") << "import runpy, sys\n"
                                         "state = runpy.run_path(sys.argv[1])\n"
                                         "view = state['view']\n"
                                         "print('camera', *view.CameraPosition, *view.CameraFocalPoint, "
                                         "view.CameraViewAngle)\n";
    const std::string command = std::string(std::getenv("DISPLAY") ? "" : "xvfb-run -a ") + pvbatch + " " +
                                (dir_ / "camera.py").string() + " " + script.string() + " > " +
                                (dir_ / "pv.log").string() + " 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << readText(dir_ / "pv.log");
    const std::string log = readText(dir_ / "pv.log");
    std::istringstream line(log.substr(log.rfind("camera ") + 7));
    double position[3], target[3], fov = 0.0;
    line >> position[0] >> position[1] >> position[2] >> target[0] >> target[1] >> target[2] >> fov;
    ASSERT_FALSE(line.fail()) << log;
    const double expectedPosition[3] = {0, 1, 2.5}, expectedTarget[3] = {0, 0.4, 0};  // kScene's camera
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_NEAR(position[axis], expectedPosition[axis], 1e-9) << log;
        EXPECT_NEAR(target[axis], expectedTarget[axis], 1e-9) << log;
    }
    EXPECT_NEAR(fov, 45.0, 1e-9);
}

// ParaView itself renders the state: the picture is not the background alone.
TEST_F(ParaViewState, ParaViewRendersTheState) {
    const char* pvbatch = std::getenv("EIKON_PVBATCH");
    if (!pvbatch) GTEST_SKIP() << "EIKON_PVBATCH does not name ParaView's pvbatch (docs/paraview.md)";
    const fs::path script = runScene();
    const fs::path picture = dir_ / "state.png";
    const std::string command = std::string(std::getenv("DISPLAY") ? "" : "xvfb-run -a ") + pvbatch + " " +
                                script.string() + " " + picture.string() + " > " + (dir_ / "pv.log").string() + " 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << readText(dir_ / "pv.log");
    const eikon::io::Rgba8Image image = eikon::io::readImage(picture);
    ASSERT_GT(image.width, 0);
    // ParaView's background is one colour; the slice, the receiver and the
    // paths between them cover a good part of the middle of the picture.
    const auto pixel = [&](int x, int y) { return &image.rgba[4 * (static_cast<std::size_t>(y) * image.width + x)]; };
    const std::uint8_t* background = pixel(0, 0);
    int differing = 0, middle = 0;
    for (int y = image.height / 4; y < 3 * image.height / 4; ++y)
        for (int x = image.width / 4; x < 3 * image.width / 4; ++x, ++middle)
            if (std::abs(pixel(x, y)[0] - background[0]) + std::abs(pixel(x, y)[1] - background[1]) +
                    std::abs(pixel(x, y)[2] - background[2]) > 30)
                ++differing;
    EXPECT_GT(differing, middle / 3) << differing << " of " << middle;
}

}  // namespace
