// The live loop as `eikon run` drives it: a simulated scene's fields through
// the field ring, pipelining, and the simulation on either device — the
// fluid solver (sim.device) and a water body (its device) — rendering the
// same frames, with what crosses the bus reported and exports reading back
// only what they export.
#include "tests/integration/CliRun.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkXMLImageDataReader.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;
using eikon::test::Outcome;
using eikon::test::readReport;
using eikon::test::runEikon;

class LiveCli : public eikon::test::CliFolderTest {
protected:
    LiveCli() : CliFolderTest("eikon_live_cli_") {}
};

// Every cell-data array of a VTK ImageData file, by name, its components flattened.
std::map<std::string, std::vector<double>> vtiArrays(const fs::path& path) {
    vtkNew<vtkXMLImageDataReader> reader;
    reader->SetFileName(path.string().c_str());
    reader->Update();
    std::map<std::string, std::vector<double>> arrays;
    vtkCellData* cells = reader->GetOutput()->GetCellData();
    for (int a = 0; a < cells->GetNumberOfArrays(); ++a) {
        vtkDataArray* array = cells->GetArray(a);
        std::vector<double>& values = arrays[array->GetName()];
        for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
            for (int c = 0; c < array->GetNumberOfComponents(); ++c) values.push_back(array->GetComponent(t, c));
    }
    return arrays;
}

std::string fileBytes(const fs::path& path) {
    std::ifstream file(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

// Runs `scene` with `arguments` twice, once with `key`=cpu into
// `folder`/cpu and once with `key`=gpu into `folder`/gpu; both must succeed.
struct DeviceRuns {
    fs::path cpu, gpu;
};
DeviceRuns runOnBothDevices(const fs::path& folder, const std::string& scene, const std::string& arguments,
                            const std::string& key) {
    const DeviceRuns runs{folder / "cpu", folder / "gpu"};
    for (const auto& [device, out] : {std::pair{"cpu", runs.cpu}, std::pair{"gpu", runs.gpu}}) {
        const Outcome outcome = runEikon("run " + scene + " --out " + out.string() + arguments + " --set " + key + "=" + device);
        EXPECT_EQ(outcome.exitCode, 0) << outcome.output;
    }
    return runs;
}

// A simulated scene's fields reach the GPU through the field ring: no field
// byte is copied on the host, and simulating the next frame during the
// render changes no pixel.
TEST_F(LiveCli, LiveSimulationCopiesNoHostBytesAndPipeliningChangesNoPixel) {
    const std::string scene = std::string(EIKON_SOURCE_DIR) + "/scenes/hot_plate_plume.json";
    const std::string small = " --frames 6 --quiet --set grid.resolution=[16,16,16] --set sim.resolution=[12,24,12]"
                              " --set render.width=48 --set render.height=36";
    const fs::path pipelined = dir_ / "pipelined", sequential = dir_ / "sequential";
    ASSERT_EQ(runEikon("run " + scene + " --out " + pipelined.string() + small + " --pipelining on").exitCode, 0);
    ASSERT_EQ(runEikon("run " + scene + " --out " + sequential.string() + small + " --pipelining off").exitCode, 0);
    const auto report = readReport(pipelined / "report.jsonl");
    ASSERT_EQ(report.size(), 6u);
    EXPECT_LE(report[0]["host_bytes_copied"].get<std::size_t>(), 64u);  // the grid's uniform block only
    for (std::size_t frame = 1; frame < report.size(); ++frame) {
        EXPECT_EQ(report[frame]["host_bytes_copied"].get<std::size_t>(), 0u) << report[frame].dump();
        EXPECT_EQ(report[frame]["gpu_bytes_copied"].get<std::size_t>(), 16u * 16u * 16u * sizeof(float));
        EXPECT_EQ(report[frame]["stages"][0]["name"], "simulate");
        EXPECT_EQ(report[frame]["stages"][0]["ran"], true);
        // frames × frame_time in one rounding: a sum of substeps read 0.19999999999999998 at frame 5
        EXPECT_EQ(report[frame]["time_s"].get<double>(), static_cast<double>(frame) * 0.04);
    }
    EXPECT_EQ(report[0]["loop"]["pipelined"], true);
    EXPECT_EQ(readReport(sequential / "report.jsonl")[0]["loop"]["pipelined"], false);
    for (const char* frame : {"frame_00001.png", "frame_00002.png"})
        EXPECT_EQ(fileBytes(pipelined / "frames" / frame), fileBytes(sequential / "frames" / frame)) << frame;
    EXPECT_NE(fileBytes(pipelined / "frames" / "frame_00000.png"), fileBytes(pipelined / "frames" / "frame_00002.png"))
        << "the plume rises between frames";
}

// sim.device "gpu" runs the solver's substeps and its optical mapping as
// compute passes (llvmpipe here), writing the field ring's slots in GPU
// memory, and renders the same frames as the CPU backend, byte for byte at
// this size. After the first frame (which uploads the initial state) only
// the solver's stopping tests, CFL count and NaN checks cross the bus — a
// few hundred bytes — where the CPU backend writes δn through the ring.
TEST_F(LiveCli, SolverOnTheGpuRendersTheCpuBackendsFrames) {
    const std::string scene = std::string(EIKON_SOURCE_DIR) + "/scenes/hot_plate_plume.json";
    const std::string small = " --frames 4 --quiet --set grid.resolution=[16,16,16] --set sim.resolution=[12,24,12]"
                              " --set render.width=48 --set render.height=36";
    const auto [cpu, gpu] = runOnBothDevices(dir_, scene, small, "sim.device");
    const auto cpuReport = readReport(cpu / "report.jsonl");
    const auto gpuReport = readReport(gpu / "report.jsonl");
    ASSERT_EQ(gpuReport.size(), 4u);
    const std::size_t ringBytes = 16u * 16u * 16u * sizeof(float);
    for (std::size_t frame = 1; frame < gpuReport.size(); ++frame) {
        EXPECT_EQ(gpuReport[frame]["simulation_device"], "gpu");
        EXPECT_EQ(cpuReport[frame]["simulation_device"], "cpu");
        EXPECT_EQ(cpuReport[frame]["bus_bytes"].get<std::size_t>(), ringBytes);
        EXPECT_EQ(gpuReport[frame]["host_bytes_copied"].get<std::size_t>(), 0u);
        EXPECT_EQ(gpuReport[frame]["loop"]["pipelined"], false);
    }
    for (std::size_t frame = 2; frame < gpuReport.size(); ++frame) {
        const auto bytes = gpuReport[frame]["bus_bytes"].get<std::size_t>();
        EXPECT_GT(bytes, 0u) << "the stopping tests read their residuals back";
        EXPECT_LT(bytes, 4096u) << "no field crosses the bus";
    }
    for (const char* frame : {"frame_00001.png", "frame_00002.png", "frame_00003.png"})
        EXPECT_EQ(fileBytes(cpu / "frames" / frame), fileBytes(gpu / "frames" / frame)) << frame;
}

// A water body's device "gpu" steps its wave equation, writes its surface
// and paints its attenuation as compute passes (llvmpipe here): after the
// first frame nothing crosses the bus, where the host path uploads the
// repainted band of κ and the water's triangles, and the frames are the
// host path's, byte for byte — eikonal (coverage kept) and image space.
TEST_F(LiveCli, WaterOnTheGpuRendersTheHostPathsFrames) {
    const std::string scene = std::string(EIKON_SOURCE_DIR) + "/scenes/pool_caustics.json";
    const std::string small = " --frames 3 --quiet --set grid.resolution=[32,16,32] --set objects.0.cells=[48,48]"
                              " --set render.width=48 --set render.height=36 --set render.photons=16384";
    for (const char* method : {"eikonal", "image_space"}) {
        const auto [cpu, gpu] =
            runOnBothDevices(dir_ / method, scene, small + " --set render.method=" + method, "objects.0.device");
        const auto cpuReport = readReport(cpu / "report.jsonl");
        const auto gpuReport = readReport(gpu / "report.jsonl");
        ASSERT_EQ(gpuReport.size(), 3u);
        for (std::size_t frame = 1; frame < gpuReport.size(); ++frame) {
            EXPECT_EQ(gpuReport[frame]["simulation_device"], "gpu") << method;
            EXPECT_EQ(cpuReport[frame]["simulation_device"], "cpu") << method;
            EXPECT_GT(cpuReport[frame]["bus_bytes"].get<std::size_t>(), 0u) << method;
            EXPECT_EQ(gpuReport[frame]["bus_bytes"].get<std::size_t>(), 0u) << method;
        }
        for (const char* frame : {"frame_00000.png", "frame_00001.png", "frame_00002.png"})
            EXPECT_EQ(fileBytes(cpu / "frames" / frame), fileBytes(gpu / "frames" / frame)) << method << " " << frame;
    }
}

// With the solver on the GPU an export reads back only what it exports,
// when it exports it: the frames between read back nothing for it, and an
// exported frame only the fields listed (here the temperature: the solver's
// scalars, not its velocity; and δn from the ring's slot in GPU memory).
// The exported values are the CPU backend's to float rounding (1e-6 of the
// largest; 9e-8 measured).
TEST_F(LiveCli, ExportsOfASolverOnTheGpuReadBackOnlyWhatTheyExport) {
    const std::string scene = std::string(EIKON_SOURCE_DIR) + "/scenes/hot_plate_plume.json";
    const std::string small = " --frames 5 --quiet --set grid.resolution=[16,16,16] --set sim.resolution=[12,24,12]"
                              " --set render.width=48 --set render.height=36 --set export.vtk.enabled=true"
                              " --set export.vtk.every=2 --set 'export.vtk.fields=[\"temperature\",\"delta_index\"]'";
    const auto [cpu, gpu] = runOnBothDevices(dir_, scene, small, "sim.device");
    const auto report = readReport(gpu / "report.jsonl");
    ASSERT_EQ(report.size(), 5u);
    const std::size_t deltaIndexBytes = 16u * 16u * 16u * sizeof(float);
    const std::size_t scalarBytes = 3u * 12u * 24u * 12u * sizeof(float);  // temperature, concentration, dye
    for (std::size_t frame = 2; frame < report.size(); ++frame) {
        const auto bytes = report[frame]["bus_bytes"].get<std::size_t>();
        if (frame % 2 == 1) {
            EXPECT_LT(bytes, 4096u) << "frame " << frame << " exports nothing: only the stopping tests";
        } else {
            EXPECT_GE(bytes, deltaIndexBytes + scalarBytes) << "frame " << frame;
            EXPECT_LT(bytes, deltaIndexBytes + scalarBytes + 4096u) << "frame " << frame << ": no velocity";
        }
    }
    for (const char* file : {"fields_00000.vti", "fields_00002.vti", "fields_00004.vti"}) {
        const auto onCpu = vtiArrays(cpu / "vtk" / file), onGpuArrays = vtiArrays(gpu / "vtk" / file);
        ASSERT_EQ(onGpuArrays.size(), 2u) << file << ": temperature and delta_index only";
        for (const auto& [name, values] : onCpu) {
            ASSERT_TRUE(onGpuArrays.count(name)) << file << " " << name;
            const std::vector<double>& other = onGpuArrays.at(name);
            ASSERT_EQ(values.size(), other.size());
            double largest = 0.0, difference = 0.0;
            for (std::size_t i = 0; i < values.size(); ++i) {
                largest = std::max(largest, std::abs(values[i]));
                difference = std::max(difference, std::abs(values[i] - other[i]));
            }
            EXPECT_LE(difference, 1e-6 * largest) << file << " " << name;
            std::printf("%s %s: largest difference %.3g of the largest value\n", file, name.c_str(), difference / largest);
        }
    }
    EXPECT_FALSE(fs::exists(gpu / "vtk" / "fields_00001.vti"));

    // Exporting the velocity takes the whole state down on the frames that
    // export it, and leaves the GPU's copy current: nothing goes back up.
    const fs::path velocity = dir_ / "velocity";
    const std::string velocityOnly = " --frames 5 --quiet --set grid.resolution=[16,16,16] --set sim.resolution=[12,24,12]"
                                     " --set render.width=48 --set render.height=36 --set export.vtk.enabled=true"
                                     " --set export.vtk.every=2 --set 'export.vtk.fields=[\"velocity\"]'";
    ASSERT_EQ(runEikon("run " + scene + " --out " + velocity.string() + velocityOnly + " --set sim.device=gpu").exitCode, 0);
    const auto velocityReport = readReport(velocity / "report.jsonl");
    ASSERT_EQ(velocityReport.size(), 5u);
    EXPECT_GE(velocityReport[2]["bus_bytes"].get<std::size_t>(), scalarBytes) << "the state, scalars with it";
    EXPECT_LT(velocityReport[3]["bus_bytes"].get<std::size_t>(), 4096u) << "no upload after the export's read";
}

}  // namespace
