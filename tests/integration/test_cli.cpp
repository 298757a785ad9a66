// The eikon executable as users meet it: exit codes, messages that name the
// file and JSON path of bad input, nothing written on refusal, and the
// output layout of a run.
#include "io/vdb/VdbVolumeFile.h"
#include "tests/integration/CliRun.h"
#include "tests/unit/VdbTestFiles.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPolyDataWriter.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;
using eikon::test::Outcome;
using eikon::test::runEikon;

class Cli : public eikon::test::CliFolderTest {
protected:
    Cli() : CliFolderTest("eikon_cli_") {}

    // A small valid scene, and below it the same with one value replaced textually.
    static std::string validScene() {
        return eikon::test::kSmallSphereScene;
    }
    static std::string replaced(const std::string& from, const std::string& to) {
        std::string text = validScene();
        const auto at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        return text.replace(at, from.size(), to);
    }
};

TEST_F(Cli, RunWritesFramesAndReport) {
    const std::string scene = writeScene("ok.json", validScene());
    const fs::path out = dir_ / "out";
    const Outcome outcome = runEikon("run " + scene + " --out " + out.string() + " --frames 2 --quiet");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    EXPECT_TRUE(fs::exists(out / "frames" / "frame_00000.png"));
    EXPECT_TRUE(fs::exists(out / "frames" / "frame_00001.png"));
    std::ifstream report(out / "report.jsonl");
    std::string line;
    int lines = 0;
    while (std::getline(report, line)) {
        ++lines;
        EXPECT_NE(line.find("\"energy_balance_error\""), std::string::npos);
        EXPECT_NE(line.find("\"name\":\"photons\""), std::string::npos);
    }
    EXPECT_EQ(lines, 2);
}

// The per-frame error estimates reach report.jsonl, and a frame whose noise
// is above render.warn_error (4096 photons on a 32² map: about 10%) is
// reported on stderr once a run, whatever the number of frames.
TEST_F(Cli, ErrorEstimatesAreReportedAndWarnedOnceAboveTheThreshold) {
    const std::string scene = writeScene("ok.json", validScene());
    const auto warnings = [](const std::string& output) {
        int count = 0;
        for (auto at = output.find("eikon: warning:"); at != std::string::npos; at = output.find("eikon: warning:", at + 1))
            ++count;
        return count;
    };
    const Outcome noisy = runEikon("run " + scene + " --out " + (dir_ / "noisy").string() + " --frames 2 --quiet");
    ASSERT_EQ(noisy.exitCode, 0) << noisy.output;
    EXPECT_EQ(warnings(noisy.output), 1) << noisy.output;
    EXPECT_NE(noisy.output.find("noise of the receiver maps"), std::string::npos) << noisy.output;
    EXPECT_NE(noisy.output.find("render.warn_error = 5%"), std::string::npos) << noisy.output;
    std::ifstream report(dir_ / "noisy" / "report.jsonl");
    for (std::string line; std::getline(report, line);) {
        const nlohmann::json estimate = nlohmann::json::parse(line).at("error_estimate");
        EXPECT_GT(estimate["noise"]["receivers"].get<double>(), 0.05);
        EXPECT_GT(estimate["noise"]["image"].get<double>(), 0.0);
        EXPECT_LT(estimate["discretisation"]["receivers"].get<double>(), 0.05);
        EXPECT_EQ(estimate["discretisation"]["probe_photons"].get<int>(), 4096);
    }

    const Outcome lenient = runEikon("run " + scene + " --out " + (dir_ / "lenient").string() +
                                     " --quiet --set render.warn_error=2");
    ASSERT_EQ(lenient.exitCode, 0) << lenient.output;
    EXPECT_EQ(warnings(lenient.output), 0) << lenient.output;

    const Outcome off = runEikon("run " + scene + " --out " + (dir_ / "off").string() +
                                 " --quiet --set render.error_estimate=false");
    ASSERT_EQ(off.exitCode, 0) << off.output;
    EXPECT_EQ(warnings(off.output), 0) << off.output;
    std::ifstream offReport(dir_ / "off" / "report.jsonl");
    std::string line;
    ASSERT_TRUE(std::getline(offReport, line));
    EXPECT_FALSE(nlohmann::json::parse(line).contains("error_estimate"));

    const Outcome bad = runEikon("run " + scene + " --out " + (dir_ / "bad").string() + " --set render.warn_error=0");
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.output.find("render.warn_error"), std::string::npos) << bad.output;
    EXPECT_FALSE(fs::exists(dir_ / "bad"));
}

TEST_F(Cli, VtkExportWritesATimeSeries) {
    const std::string scene = writeScene("ok.json", validScene());
    const fs::path out = dir_ / "out";
    const Outcome outcome = runEikon("run " + scene + " --out " + out.string() + " --frames 2 --quiet --vtk");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    EXPECT_TRUE(fs::exists(out / "vtk" / "fields_00000.vti"));
    EXPECT_TRUE(fs::exists(out / "vtk" / "fields_00001.vti"));
    std::ifstream collection(out / "vtk" / "fields.pvd");
    std::stringstream text;
    text << collection.rdbuf();
    EXPECT_NE(text.str().find("fields_00001.vti"), std::string::npos) << text.str();
    EXPECT_TRUE(fs::exists(out / "vtk" / "fields.vti.series"));
}

// The scene's export section picks frames, fields and compression; --vtk
// turns it on and keeps them, with what --set changes.
TEST_F(Cli, SceneExportSectionSelectsFramesAndFields) {
    std::string text = validScene();
    text.insert(text.rfind('}'), R"(, "export": {"vtk": {"every": 2, "fields": ["delta_index", "fluence"], "compression": "none"}})");
    const std::string scene = writeScene("export.json", text);
    const fs::path out = dir_ / "out";
    Outcome outcome = runEikon("run " + scene + " --out " + out.string() + " --frames 3 --quiet");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    EXPECT_TRUE(fs::exists(out / "vtk" / "fields_00000.vti"));
    EXPECT_FALSE(fs::exists(out / "vtk" / "fields_00001.vti"));
    EXPECT_TRUE(fs::exists(out / "vtk" / "fields_00002.vti"));
    std::ifstream frame(out / "vtk" / "fields_00002.vti", std::ios::binary);
    std::string head(1500, '\0');
    frame.read(head.data(), static_cast<std::streamsize>(head.size()));
    EXPECT_NE(head.find("Name=\"delta_index\""), std::string::npos) << head;
    EXPECT_NE(head.find("Name=\"fluence\" NumberOfComponents=\"3\""), std::string::npos) << head;
    EXPECT_EQ(head.find("Name=\"index\""), std::string::npos) << head;
    EXPECT_EQ(head.find("compressor="), std::string::npos) << head;
    EXPECT_TRUE(fs::exists(out / "vtk" / "receivers_00002.vtp"));  // the scene's receiver, as quads
    EXPECT_TRUE(fs::exists(out / "vtk" / "receivers.vtp.series"));
    EXPECT_FALSE(fs::exists(out / "vtk" / "photon_paths_00000.vtp"));  // not asked for

    outcome = runEikon("run " + scene + " --out " + out.string() +
                       " --frames 2 --quiet --force --vtk --set export.vtk.compression=zlib");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    EXPECT_FALSE(fs::exists(out / "vtk" / "fields_00001.vti")) << "the scene's every: 2";
    std::ifstream forced(out / "vtk" / "fields_00000.vti", std::ios::binary);
    forced.read(head.data(), static_cast<std::streamsize>(head.size()));
    EXPECT_EQ(head.find("Name=\"index\""), std::string::npos) << "the scene's fields: " << head;
    EXPECT_NE(head.find("vtkZLibDataCompressor"), std::string::npos) << "--set's compression: " << head;
}

// A Blender-style OpenVDB sequence imported for three frames and exported
// again: the exported temperature of frame f is the mapping of file f + 1.
TEST_F(Cli, VolumeSequenceRunsAndExportsOpenVdb) {
    for (int f = 1; f <= 3; ++f) {
        char name[64];
        std::snprintf(name, sizeof name, "fluid_data_%04d.vdb", f);
        eikon::test::writeVdbFile(dir_ / name,
                                  {{"density", 1, [](double, double, double, int) { return 0.5f; }},
                                   {"temperature", 1, [f](double, double, double, int) { return float(f); }}},
                                  0.05, -0.6, 0.6);
    }
    std::string text = validScene();
    text.insert(text.rfind('}'), R"(, "volume": {"path": "fluid_data_####.vdb", "temperature_scale": 10,
        "density_extinction": 0.5}, "export": {"vdb": {"fields": ["temperature", "extinction", "index"]}})");
    const std::string scene = writeScene("volume.json", text);
    const fs::path out = dir_ / "out";
    // Four frames need fluid_data_0004.vdb: refused before anything is written.
    const Outcome refused = runEikon("run " + scene + " --out " + out.string() + " --frames 4 --quiet");
    EXPECT_EQ(refused.exitCode, 2) << refused.output;
    EXPECT_NE(refused.output.find("fluid_data_0004.vdb: expected the volume sequence's file for rendered frame 3, "
                                  "found no such file"),
              std::string::npos)
        << refused.output;
    EXPECT_FALSE(fs::exists(out));
    const Outcome outcome = runEikon("run " + scene + " --out " + out.string() + " --frames 3 --quiet");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    const eikon::GridSpec cell{{1, 1, 1}, {0.1, 0.1, 0.1}, {0.1625, 0.1625, 0.1625}};  // one cell of the 16³ grid, away from the sphere
    for (int frame = 0; frame < 3; ++frame) {
        char name[64];
        std::snprintf(name, sizeof name, "fields_%05d.vdb", frame);
        const eikon::io::VdbVolumeFile file(out / "vdb" / name);
        EXPECT_EQ(file.gridNames(), (std::vector<std::string>{"index", "extinction", "temperature"}));
        EXPECT_FLOAT_EQ(file.sample("temperature", 1, cell, {0, 0, 0})[0], 293.15f + 10.0f * float(frame + 1));
        EXPECT_FLOAT_EQ(file.sample("extinction", 3, cell, {0, 0, 0})[1], 0.25f);
    }
}

// VTK input from the command line: a .vtp is surface data, refused with
// exit 2 before anything is written; a .pvd of two image-data steps (T in
// kelvin) refuses a third frame before anything is written, and renders two,
// frame k showing step k in the exported temperature.
TEST_F(Cli, VtkTimeSeriesRunsAndSurfaceDataIsRefused) {
    vtkNew<vtkPolyData> surface;
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(0, 0, 0);
    surface->SetPoints(points);
    vtkNew<vtkXMLPolyDataWriter> surfaceWriter;
    surfaceWriter->SetFileName((dir_ / "surface.vtp").c_str());
    surfaceWriter->SetInputData(surface);
    ASSERT_EQ(surfaceWriter->Write(), 1);
    for (int step = 0; step < 2; ++step) {
        vtkNew<vtkImageData> image;  // covers the scene's grid, [-0.5, 0.5] × [0, 1] × [-0.5, 0.5]
        image->SetDimensions(5, 5, 5);
        image->SetSpacing(0.25, 0.25, 0.25);
        image->SetOrigin(-0.5, 0.0, -0.5);
        vtkNew<vtkDoubleArray> t;
        t->SetName("T");
        for (int p = 0; p < 125; ++p) t->InsertNextValue(300.0 + 100.0 * step);
        image->GetPointData()->AddArray(t);
        vtkNew<vtkXMLImageDataWriter> writer;
        writer->SetFileName((dir_ / ("step_" + std::to_string(step) + ".vti")).c_str());
        writer->SetInputData(image);
        ASSERT_EQ(writer->Write(), 1);
    }
    std::ofstream(dir_ / "flow.pvd") << R"(<?xml version="1.0"?>
<VTKFile type="Collection" version="0.1"><Collection>
  <DataSet timestep="0" file="step_0.vti"/><DataSet timestep="1" file="step_1.vti"/>
</Collection></VTKFile>)";
    const auto sceneFor = [&](const std::string& path) {
        std::string text = validScene();
        text.insert(text.rfind('}'), R"(, "volume": {"path": ")" + path +
                                         R"(", "fields": {"temperature": "T", "temperature_unit": "kelvin"}},
            "export": {"vdb": {"fields": ["temperature"]}})");
        return writeScene(path + ".json", text);
    };
    const fs::path out = dir_ / "out";
    const Outcome surfaceRun = runEikon("run " + sceneFor("surface.vtp") + " --out " + out.string() + " --quiet");
    EXPECT_EQ(surfaceRun.exitCode, 2) << surfaceRun.output;
    EXPECT_NE(surfaceRun.output.find("surface.vtp: expected volume data"), std::string::npos) << surfaceRun.output;
    EXPECT_NE(surfaceRun.output.find("found polygonal data: a surface"), std::string::npos) << surfaceRun.output;
    EXPECT_FALSE(fs::exists(out));
    const std::string scene = sceneFor("flow.pvd");
    const Outcome tooMany = runEikon("run " + scene + " --out " + out.string() + " --frames 3 --quiet");
    EXPECT_EQ(tooMany.exitCode, 2) << tooMany.output;
    EXPECT_NE(tooMany.output.find("expected a time step for each of the 3 rendered frames (rendered frame k shows "
                                  "step k), found 2 steps"),
              std::string::npos)
        << tooMany.output;
    EXPECT_FALSE(fs::exists(out));
    const Outcome outcome = runEikon("run " + scene + " --out " + out.string() + " --frames 2 --quiet");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    const eikon::GridSpec cell{{1, 1, 1}, {0.1, 0.1, 0.1}, {0.1625, 0.1625, 0.1625}};
    for (int frame = 0; frame < 2; ++frame) {
        char name[64];
        std::snprintf(name, sizeof name, "fields_%05d.vdb", frame);
        const eikon::io::VdbVolumeFile file(out / "vdb" / name);
        EXPECT_FLOAT_EQ(file.sample("temperature", 1, cell, {0, 0, 0})[0], 300.0f + 100.0f * float(frame));
    }
}

// The last file of a three-file sequence cut short, overwritten with text,
// or damaged inside its last grid's tree (its length kept): each stops the
// run before frame 0 is written, exit 2 naming the scene, volume.path and that
// file, and no output folder, though frames 0 and 1 would render.
TEST_F(Cli, ADamagedLaterFileOfASequenceStopsTheRunBeforeFrameZero) {
    for (int f = 1; f <= 3; ++f) {
        char name[64];
        std::snprintf(name, sizeof name, "fluid_data_%04d.vdb", f);
        eikon::test::writeVdbFile(dir_ / name,
                                  {{"density", 1, [](double, double, double, int) { return 0.5f; }},
                                   {"temperature", 1, [f](double x, double, double, int) { return float(f * x); }}},
                                  0.05, -0.6, 0.6);
    }
    std::string text = validScene();
    text.insert(text.rfind('}'), R"(, "volume": {"path": "fluid_data_####.vdb", "temperature_scale": 10,
        "density_extinction": 0.5})");
    const std::string scene = writeScene("volume.json", text);
    const fs::path last = dir_ / "fluid_data_0003.vdb", out = dir_ / "out";
    std::string whole;
    {
        std::ifstream in(last, std::ios::binary);
        whole.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    std::string damaged = whole;
    std::fill(damaged.end() - 400, damaged.end() - 8, '\x55');  // inside the temperature grid's leaf buffers
    for (const auto& [label, bytes] : {std::pair<std::string, std::string>{"truncated", whole.substr(0, whole.size() / 2)},
                                       {"garbage", std::string(whole.size(), 'x')},
                                       {"damaged tree", damaged}}) {
        SCOPED_TRACE(label);
        std::ofstream(last, std::ios::binary | std::ios::trunc) << bytes;
        const Outcome outcome = runEikon("run " + scene + " --out " + out.string() + " --frames 3 --quiet");
        EXPECT_EQ(outcome.exitCode, 2) << outcome.output;
        EXPECT_EQ(outcome.output.rfind("eikon: error: " + scene + ": volume.path: " + last.string() + ": ", 0), 0u)
            << outcome.output;
        EXPECT_FALSE(fs::exists(out)) << "frames 0 and 1 were written before the damaged file was found";
    }
    EXPECT_EQ(runEikon("run " + scene + " --out " + out.string() + " --frames 2 --quiet").exitCode, 0)
        << "the frames before the damaged file render";
}

// A deforming mesh goes to ParaView too: each frame's deformed mesh as .vtp.
// The wavefront lights a scattering medium too: the frame renders and its
// report counts the tubes whose axes carried the patches' power into the
// fluence grid.
TEST_F(Cli, WavefrontLightsAScatteringMedium) {
    const std::string scene = writeScene(
        "smoky.json", replaced(R"("medium": {"index": 1.0})",
                               R"("medium": {"index": 1.0, "extinction": 0.5, "scattering": 0.4})"));
    const fs::path out = dir_ / "out";
    const Outcome outcome =
        runEikon("run " + scene + " --out " + out.string() + " --quiet --set 'tracer.estimator=\"wavefront\"'" +
                 " --set tracer.wavefront.split_voxels=2");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    std::ifstream report(out / "report.jsonl");
    std::string first;
    std::getline(report, first);
    const nlohmann::json photons = nlohmann::json::parse(first)["photons"];
    EXPECT_EQ(photons["estimator"], "wavefront") << first;
    EXPECT_GT(photons["wavefront"]["tubes"].get<long long>(), 0) << first;
    EXPECT_GT(photons["voxel_deposits"].get<long long>(), 0) << first;
}

// Multiple scattering by --set: the first frame's report carries the
// lattice's steps and ledger; the second frame of a static scene runs no
// lattice (nothing changed) and reports none.
TEST_F(Cli, MultipleScatteringReachesTheReport) {
    const std::string scene = writeScene(
        "milky.json", replaced(R"("medium": {"index": 1.0})",
                               R"("medium": {"index": 1.0, "extinction": 4, "scattering": 3.6})"));
    const fs::path out = dir_ / "out";
    const Outcome outcome = runEikon("run " + scene + " --out " + out.string() +
                                     " --frames 2 --quiet --set 'tracer.multiple_scattering=\"lbm\"'");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    std::ifstream report(out / "report.jsonl");
    std::string first, second;
    std::getline(report, first);
    std::getline(report, second);
    const nlohmann::json frame = nlohmann::json::parse(first);
    ASSERT_TRUE(frame.contains("multiple_scattering")) << first;
    const nlohmann::json& lattice = frame["multiple_scattering"];
    EXPECT_EQ(lattice["directions"], 14);
    EXPECT_GT(lattice["iterations"][0].get<int>(), 0);
    EXPECT_GT(lattice["power_w"]["source"][0].get<double>(), 0.0);
    EXPECT_LT(lattice["energy_balance_error"].get<double>(), 1e-2);
    EXPECT_NE(first.find("\"name\":\"multiple_scattering\",\"ran\":true"), std::string::npos) << first;
    EXPECT_NE(second.find("\"name\":\"multiple_scattering\",\"ran\":false"), std::string::npos) << second;
    EXPECT_FALSE(nlohmann::json::parse(second).contains("multiple_scattering"));
}

TEST_F(Cli, VtkExportWritesEachFramesDeformedMesh) {
    const std::string scene = std::string(EIKON_SOURCE_DIR) + "/scenes/twisting_glass.json";
    const fs::path out = dir_ / "out";
    const Outcome outcome = runEikon("run " + scene + " --out " + out.string() +
                                     " --frames 2 --quiet --vtk --set grid.resolution=[24,28,24] "
                                     "--set render.photons=4096 --set render.width=32 --set render.height=24");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    const fs::path first = out / "vtk" / "meshes_00000.vtp", second = out / "vtk" / "meshes_00001.vtp";
    ASSERT_TRUE(fs::exists(first));
    ASSERT_TRUE(fs::exists(second));
    EXPECT_TRUE(fs::exists(out / "vtk" / "meshes.vtp.series"));
    std::ifstream a(first, std::ios::binary), b(second, std::ios::binary);
    const std::string textA{std::istreambuf_iterator<char>(a), {}}, textB{std::istreambuf_iterator<char>(b), {}};
    EXPECT_NE(textA.find("Name=\"object\""), std::string::npos);
    EXPECT_NE(textA, textB) << "the bar twists between frames";
}

TEST_F(Cli, SecondFrameOfStaticSceneRunsNoStage) {
    const std::string scene = writeScene("ok.json", validScene());
    const fs::path out = dir_ / "out";
    ASSERT_EQ(runEikon("run " + scene + " --out " + out.string() + " --frames 2 --quiet").exitCode, 0);
    std::ifstream report(out / "report.jsonl");
    std::string first, second;
    std::getline(report, first);
    std::getline(report, second);
    EXPECT_NE(first.find("\"name\":\"photons\",\"ran\":true"), std::string::npos) << first;
    EXPECT_NE(second.find("\"name\":\"photons\",\"ran\":false"), std::string::npos) << second;
    EXPECT_NE(second.find("\"name\":\"view\",\"ran\":false"), std::string::npos) << second;
    EXPECT_NE(second.find("\"name\":\"upload\",\"ran\":false"), std::string::npos) << second;
    EXPECT_EQ(first.find("\"simulate\""), std::string::npos) << "a scene without fluid has no simulation stage";
}

TEST_F(Cli, RefusesEarlierRunUnlessForced) {
    const std::string scene = writeScene("ok.json", validScene());
    const std::string out = (dir_ / "out").string();
    ASSERT_EQ(runEikon("run " + scene + " --out " + out + " --quiet").exitCode, 0);
    const Outcome refused = runEikon("run " + scene + " --out " + out + " --quiet");
    EXPECT_EQ(refused.exitCode, 2);
    EXPECT_NE(refused.output.find("--force"), std::string::npos) << refused.output;
    EXPECT_EQ(runEikon("run " + scene + " --out " + out + " --quiet --force").exitCode, 0);
}

struct BadInput {
    const char* name;
    const char* from;
    const char* to;
    const char* path;  // the JSON path the message must name
};

const BadInput kBadInputs[] = {
    {"unknown top-level key", "\"medium\":", "\"mediun\":", "mediun"},
    {"unknown nested key", "\"radius\": 0.2", "\"radios\": 0.2", "objects[0].radios"},
    {"wrong type", "\"radius\": 0.2", "\"radius\": \"big\"", "objects[0].radius"},
    {"index not positive", "\"index\": 1.5", "\"index\": 0", "objects[0].index"},
    {"negative medium index", "\"medium\": {\"index\": 1.0}", "\"medium\": {\"index\": -1.0}", "medium.index"},
    {"negative extinction", "\"medium\": {\"index\": 1.0}", "\"medium\": {\"index\": 1.0, \"extinction\": [0, -1, 0]}",
     "medium.extinction"},
    {"zero resolution", "[16, 16, 16]", "[16, 0, 16]", "grid.resolution"},
    {"empty bounds", "\"max\": [0.5, 1, 0.5]", "\"max\": [0.5, 0, 0.5]", "grid.bounds"},
    {"vector too short", "\"center\": [0, 0.5, 0]", "\"center\": [0, 0.5]", "objects[0].center"},
    {"unknown object type", "\"type\": \"sphere\"", "\"type\": \"cone\"", "objects[0].type"},
    {"number overflow", "\"radius\": 0.2", "\"radius\": 1e999", "ok.json: line "},
    {"camera looks at itself", "\"target\": [0, 0.3, 0]", "\"target\": [0, 1, 2]", "camera.target"},
    {"photons zero", "\"photons\": 4096", "\"photons\": 0", "render.photons"},
    {"fov out of range", "\"fov_deg\": 45", "\"fov_deg\": 200", "camera.fov_deg"},
};

TEST_F(Cli, BadSceneInputsExitWithCodeTwoAndNameThePath) {
    for (const BadInput& bad : kBadInputs) {
        const std::string scene = writeScene("ok.json", replaced(bad.from, bad.to));
        const fs::path out = dir_ / "never";
        const Outcome outcome = runEikon("run " + scene + " --out " + out.string() + " --quiet");
        EXPECT_EQ(outcome.exitCode, 2) << bad.name << ": " << outcome.output;
        EXPECT_NE(outcome.output.find("ok.json"), std::string::npos) << bad.name << ": " << outcome.output;
        EXPECT_NE(outcome.output.find(bad.path), std::string::npos) << bad.name << ": " << outcome.output;
        EXPECT_FALSE(fs::exists(out)) << bad.name << ": nothing may be written for bad input";
    }
}

// A scene whose mesh file is truncated: exit code 2, the scene's JSON path
// and the mesh file's own complaint, nothing written.
TEST_F(Cli, BadMeshFileExitsWithCodeTwoAndNamesSceneAndFile) {
    const fs::path mesh = dir_ / "cut.off";
    std::ofstream(mesh) << "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n";
    const std::string object = R"({"type": "mesh", "mesh": {"path": ")" + mesh.string() + R"("}, "index": 1.5})";
    const std::string scene =
        writeScene("ok.json", replaced(R"({"type": "sphere", "center": [0, 0.5, 0], "radius": 0.2, "index": 1.5})", object));
    const fs::path out = dir_ / "never";
    const Outcome outcome = runEikon("run " + scene + " --out " + out.string() + " --quiet");
    EXPECT_EQ(outcome.exitCode, 2) << outcome.output;
    EXPECT_NE(outcome.output.find("ok.json: objects[0].mesh.path"), std::string::npos) << outcome.output;
    EXPECT_NE(outcome.output.find("cut.off"), std::string::npos) << outcome.output;
    EXPECT_NE(outcome.output.find("truncated"), std::string::npos) << outcome.output;
    EXPECT_FALSE(fs::exists(out));
}

TEST_F(Cli, BadOverrideNamesItsPath) {
    const std::string scene = writeScene("ok.json", validScene());
    const Outcome outcome = runEikon("run " + scene + " --out " + (dir_ / "o").string() + " --set render.width=-3");
    EXPECT_EQ(outcome.exitCode, 2);
    EXPECT_NE(outcome.output.find("render.width"), std::string::npos) << outcome.output;
}

TEST_F(Cli, MissingSceneFileAndBadJson) {
    EXPECT_EQ(runEikon("run " + (dir_ / "absent.json").string()).exitCode, 2);
    const std::string broken = writeScene("broken.json", "{\n  \"grid\": {\n    \"resolution\": [1, 2,, 3]\n}");
    const Outcome outcome = runEikon("run " + broken);
    EXPECT_EQ(outcome.exitCode, 2);
    EXPECT_NE(outcome.output.find("broken.json: line 3"), std::string::npos) << outcome.output;
}

// Photons stopped in flight (here by tracer.max_steps at tiny uniform
// steps) are counted as cut off, so the energy balance holds, and the run
// says on stderr that power was lost.
TEST_F(Cli, PhotonsCutOffInFlightAreCountedAndReported) {
    const std::string scene = writeScene("ok.json", validScene());
    const fs::path out = dir_ / "run";
    const Outcome outcome = runEikon("run " + scene + " --out " + out.string() +
                                     " --quiet --set 'tracer.step_policy=\"uniform\"' --set tracer.step_voxels=0.01"
                                     " --set tracer.max_steps=1000");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    EXPECT_NE(outcome.output.find("eikon: warning: frame 0:"), std::string::npos) << outcome.output;
    std::ifstream report(out / "report.jsonl");
    const nlohmann::json line = nlohmann::json::parse(std::string(std::istreambuf_iterator<char>(report), {}));
    EXPECT_GT(line["photons"]["count"]["cut_off"].get<long long>(), 0);
    EXPECT_LT(line["photons"]["energy_balance_error"].get<double>(), 1e-6);
}

// The reproducer of photons lost at llvmpipe's loop cap (uniform steps of
// 0.01 voxel, about 1000 a photon): with tracer.max_steps at 10^6 every
// photon ends by its own fate — the cap suspends and resumes it, where the
// driver has one — and none is cut off.
TEST_F(Cli, MaxStepsNotTheDriversLoopCapStopsPhotons) {
    const std::string scene = writeScene("ok.json", validScene());
    const fs::path out = dir_ / "run";
    const Outcome outcome = runEikon("run " + scene + " --out " + out.string() +
                                     " --quiet --set 'tracer.step_policy=\"uniform\"' --set tracer.step_voxels=0.01"
                                     " --set tracer.max_steps=1000000 --set render.error_estimate=false");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    EXPECT_EQ(outcome.output.find("warning"), std::string::npos) << outcome.output;
    std::ifstream report(out / "report.jsonl");
    const nlohmann::json line = nlohmann::json::parse(std::string(std::istreambuf_iterator<char>(report), {}));
    EXPECT_EQ(line["photons"]["count"]["cut_off"].get<long long>(), 0);
    EXPECT_GT(line["photons"]["count"]["received"].get<long long>(), 500);
    EXPECT_LT(line["photons"]["energy_balance_error"].get<double>(), 1e-6);
    EXPECT_GT(line["photons"]["power_w"]["stated"][1].get<double>(), 0.0);
    EXPECT_LT(line["photons"]["emission_error"].get<double>(), 1e-3);
    EXPECT_TRUE(line["photons"]["resumed"].contains("photons"));
}

// SIGTERM in the middle of a run that writes VTK and OpenVDB every frame:
// eikon ends by the signal as a program does, and removes the temporaries it
// was writing, so only whole files remain under final names.
TEST_F(Cli, SigtermLeavesNoTemporaries) {
    const std::string scene = std::string(EIKON_SOURCE_DIR) + "/scenes/hot_plate_plume.json";
    const fs::path out = dir_ / "run";
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        const std::string outArgument = out.string();
        execl(EIKON_EXECUTABLE, EIKON_EXECUTABLE, "run", scene.c_str(), "--out", outArgument.c_str(), "--frames", "500",
              "--quiet", "--vtk", "--set", "export.vdb.enabled=true", "--set", "render.width=64", "--set",
              "render.height=48", "--set", "render.photons=4096", static_cast<char*>(nullptr));
        _exit(127);
    }
    // Until some frames are written, then a little longer: the signal lands
    // while frames are being exported.
    for (int wait = 0; wait < 600 && !fs::exists(out / "vtk" / "fields_00002.vti"); ++wait)
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    std::this_thread::sleep_for(std::chrono::milliseconds(150));
    ASSERT_EQ(kill(child, SIGTERM), 0);
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the run finished before the signal";
    EXPECT_EQ(WTERMSIG(status), SIGTERM);
    int files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(out)) {
        ++files;
        EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
    }
    EXPECT_GT(files, 6);
}

TEST_F(Cli, BadCommandLineIsExitCodeTwo) {
    EXPECT_EQ(runEikon("run").exitCode, 2);
    EXPECT_EQ(runEikon("frobnicate").exitCode, 2);
    const Outcome outcome = runEikon("run x.json --frames 0");
    EXPECT_EQ(outcome.exitCode, 2);
    EXPECT_EQ(outcome.output.rfind("eikon: error: ", 0), 0u) << "every message in eikon's form: " << outcome.output;
}

TEST_F(Cli, HelpOnEveryCommand) {
    for (const char* command : {"--help", "run --help", "info --help"}) {
        const Outcome outcome = runEikon(command);
        EXPECT_EQ(outcome.exitCode, 0) << command;
        EXPECT_NE(outcome.output.find("Usage"), std::string::npos) << command << ": " << outcome.output;
    }
}

// Without a usable OpenGL 4.5 context the run stops with a message naming
// what was tried (exit code 1: not the user's input), and writes no frames.
// Forcing the EGL device platform finds no context on a machine without a GPU.
TEST_F(Cli, NoOpenGlContextIsAClearError) {
    const std::string scene = writeScene("ok.json", validScene());
    const fs::path out = dir_ / "out";
    const Outcome outcome =
        runEikon("run " + scene + " --out " + out.string() + " --quiet", "EIKON_EGL_PLATFORM=device");
    if (outcome.exitCode == 0) GTEST_SKIP() << "this machine has a GPU reachable through the EGL device platform";
    EXPECT_EQ(outcome.exitCode, 1) << outcome.output;
    EXPECT_NE(outcome.output.find("no headless OpenGL 4.5 core context"), std::string::npos) << outcome.output;
    EXPECT_NE(outcome.output.find("EGL device platform"), std::string::npos) << outcome.output;
    EXPECT_FALSE(fs::exists(out)) << "nothing may be written";
}

TEST_F(Cli, InfoNamesTheOpenGlRenderer) {
    const Outcome outcome = runEikon("info");
    EXPECT_EQ(outcome.exitCode, 0);
    EXPECT_NE(outcome.output.find("OpenGL renderer:"), std::string::npos) << outcome.output;
    EXPECT_NE(outcome.output.find("OpenVDB"), std::string::npos);
}

}  // namespace

namespace {

// `eikon accuracy` on one case writes the CSV (its columns, one row per run
// and measure, finite errors), the plot and the report; an unknown case is a
// command-line error (exit 2) that lists the cases, before anything is traced.
class AccuracyCli : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("eikon_cli_accuracy_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

TEST_F(AccuracyCli, WritesCsvPlotAndReportForOneCase) {
    const Outcome outcome = runEikon("accuracy --quick --case beer_lambert --out " + dir_.string(), "LP_NUM_THREADS=2");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    std::ifstream csv(dir_ / "accuracy.csv");
    std::string header, row;
    std::getline(csv, header);
    EXPECT_EQ(header.rfind("case,integrator,step_policy,sweep,step_voxels", 0), 0u) << header;
    for (const char* column : {",grid,", ",photons,", ",runtime_s,", ",error,", ",error_metric,", ",invariant_max,",
                               ",energy_balance", ",method,"})
        EXPECT_NE(header.find(column), std::string::npos) << column;
    int rows = 0;
    while (std::getline(csv, row)) {
        ++rows;
        EXPECT_EQ(row.rfind("beer_lambert,", 0), 0u) << row;
        EXPECT_NE(row.find(",eikonal,"), std::string::npos) << row;
        EXPECT_EQ(row.find("nan"), std::string::npos) << row;
    }
    EXPECT_GE(rows, 10);
    EXPECT_GT(fs::file_size(dir_ / "accuracy.png"), 10000u);
    std::ifstream md(dir_ / "accuracy.md");
    std::stringstream report;
    report << md.rdbuf();
    EXPECT_NE(report.str().find("cheapest ≤ 1%"), std::string::npos);
}

// Every measurement of a case rests on samples: the invariant of the linear
// slab is read where paths leave its far face for a screen beyond it (an
// escaping path ends on the grid's boundary, without its exit direction).
TEST_F(AccuracyCli, EveryLinearSlabMeasurementHasSamples) {
    const Outcome outcome = runEikon("accuracy --quick --case linear_slab --out " + dir_.string(), "LP_NUM_THREADS=2");
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    std::ifstream csv(dir_ / "accuracy.csv");
    std::string header, row;
    std::getline(csv, header);
    ASSERT_NE(header.find(",samples,"), std::string::npos) << header;
    int rows = 0;
    while (std::getline(csv, row)) {
        const std::vector<std::string> cells = eikon::test::csvCells(row);  // samples: the 17th
        ASSERT_GT(cells.size(), 16u) << row;
        EXPECT_GT(std::stoi(cells[16]), 10) << row;
        ++rows;
    }
    EXPECT_GE(rows, 20);
}

TEST_F(AccuracyCli, UnknownCaseIsAnInputError) {
    const Outcome outcome = runEikon("accuracy --case nosuch --out " + dir_.string());
    EXPECT_EQ(outcome.exitCode, 2) << outcome.output;
    EXPECT_NE(outcome.output.find("--case: expected one of point_light, beer_lambert"), std::string::npos)
        << outcome.output;
    EXPECT_FALSE(fs::exists(dir_ / "accuracy.csv"));
}

}  // namespace
