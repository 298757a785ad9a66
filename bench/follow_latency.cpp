// Follow latency (`eikon run --follow`, docs/benchmarks-vtk-input.md): the
// wall time from a step's file appearing, complete, in a .series that a
// simulation writes to the frame that shows it being written (its line in
// report.jsonl, which comes after its image and exports).
//
// The writer here is the simulation: it renames each 64³ .vti step into
// place (so it appears whole at one moment) and then the index, at a random
// phase against eikon's looks (seeded), after the previous frame is out.
// eikon follows with --follow-poll-ms P: it sees the step at its next look
// and, unchanged at the look after, reads it, so the wait alone is between P
// and 2P. The scene is a 64³ render grid seen through a schlieren system,
// 256² pixels. Prints each step's latency and the frame's own figures.
//
//   bench_follow_latency [--steps N] [--poll-ms P] [--keep DIR]
// Not run by ctest.
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataWriter.h>

#include <nlohmann/json.hpp>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr int kN = 64;

// Step s: a hot column (450 K over ambient on its axis, absolute kelvin) whose axis moves along x with s.
void writeStep(const fs::path& path, int s) {
    vtkNew<vtkImageData> image;
    image->SetDimensions(kN, kN, kN);
    image->SetSpacing(1.0 / kN, 1.0 / kN, 1.0 / kN);
    image->SetOrigin(0.5 / kN, 0.5 / kN, 0.5 / kN);
    vtkNew<vtkFloatArray> t;
    t->SetName("T");
    const double axis = 0.35 + 0.03 * (s % 10);
    for (int k = 0; k < kN; ++k)
        for (int j = 0; j < kN; ++j)
            for (int i = 0; i < kN; ++i) {
                const double x = (i + 0.5) / kN - axis, z = (k + 0.5) / kN - 0.5;
                const double rise = (j + 0.5) / kN;  // cools as it rises
                t->InsertNextValue(static_cast<float>(293.15 + 450.0 * (1.0 - 0.6 * rise) *
                                                                   std::exp(-(x * x + z * z) / 0.004)));
            }
    image->GetPointData()->AddArray(t);
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetFileName(path.c_str());
    writer->SetInputData(image);
    writer->Write();
}

void writeIndex(const fs::path& folder, int steps) {
    std::string files;
    for (int s = 0; s < steps; ++s)
        files += (s ? ", " : "") + std::string(R"({"name": "step_)") + std::to_string(s) + R"(.vti", "time": )" +
                 std::to_string(s) + "}";
    const fs::path temporary = folder / "run.vti.series.tmp";
    std::ofstream(temporary) << R"({"file-series-version": "1.0", "files": [)" << files << "]}";
    fs::rename(temporary, folder / "run.vti.series");
}

std::size_t reportLines(const fs::path& report) {
    std::ifstream in(report);
    std::size_t lines = 0;
    for (std::string line; std::getline(in, line);) ++lines;
    return lines;
}

nlohmann::json lastLine(const fs::path& report) {
    std::ifstream in(report);
    std::string last;
    for (std::string line; std::getline(in, line);) last = line;
    return nlohmann::json::parse(last);
}

}  // namespace

int main(int argc, char** argv) {
    int steps = 10;
    double pollMs = 250.0;
    fs::path keep;
    for (int a = 1; a + 1 < argc; a += 2) {
        const std::string option = argv[a];
        if (option == "--steps") steps = std::atoi(argv[a + 1]);
        else if (option == "--poll-ms") pollMs = std::atof(argv[a + 1]);
        else if (option == "--keep") keep = argv[a + 1];
    }
    const fs::path folder = keep.empty() ? fs::temp_directory_path() / "eikon_follow_latency" : keep;
    fs::remove_all(folder);
    fs::create_directories(folder);
    std::ofstream(folder / "scene.json") << R"({
  "grid": {"resolution": [64, 64, 64], "bounds": {"min": [0, 0, 0], "max": [1, 1, 1]}, "smoothing_sigma_voxels": 0},
  "medium": {"index": 1.000273},
  "lights": [{"type": "directional", "direction": [0.0, -1.0, 0.0], "irradiance": [1.0, 1.0, 1.0]}],
  "camera": {"position": [0.5, 0.5, 3.0], "target": [0.5, 0.5, 0.5], "up": [0, 1, 0],
             "projection": "orthographic", "width_m": 1.0},
  "render": {"width": 256, "height": 256, "write_hdr": false},
  "diagnostic": {"type": "schlieren", "focal_length": 2.0, "source_height": 0.001,
                 "cutoff": "knife_edge", "knife_angle_deg": 90},
  "volume": {"path": "run.vti.series", "fields": {"temperature": "T", "temperature_unit": "kelvin"}}
})";
    writeIndex(folder, 0);
    const fs::path out = folder / "out";
    const fs::path report = out / "report.jsonl";
    char pollText[32];
    std::snprintf(pollText, sizeof pollText, "%g", pollMs);
    const std::string scene = (folder / "scene.json").string(), outText = out.string(),
                      stop = (folder / "done").string();
    const pid_t child = fork();
    if (child == 0) {
        execl(EIKON_EXECUTABLE, EIKON_EXECUTABLE, "run", scene.c_str(), "--out", outText.c_str(), "--quiet",
              "--follow", "--follow-poll-ms", pollText, "--follow-timeout", "600", "--follow-stop", stop.c_str(),
              static_cast<char*>(nullptr));
        _exit(127);
    }
    std::mt19937 random(55);
    std::vector<double> latencies;
    double frameMs = 0.0;  // steps 1 … N−1 together
    std::printf("step  latency_ms  frame_ms  render_ms\n");
    for (int s = 0; s < steps; ++s) {
        const fs::path temporary = folder / "step.tmp";
        writeStep(temporary, s);
        // A random phase against eikon's looks.
        std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(
            std::uniform_real_distribution<double>(0.0, pollMs)(random)));
        fs::rename(temporary, folder / ("step_" + std::to_string(s) + ".vti"));
        writeIndex(folder, s + 1);
        const auto appeared = Clock::now();
        while (!fs::exists(report) || reportLines(report) < static_cast<std::size_t>(s + 1)) {
            int status = 0;
            if (waitpid(child, &status, WNOHANG) == child) {
                std::fprintf(stderr, "eikon ended early (status %d)\n", status);
                return 1;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - appeared).count();
        const nlohmann::json line = lastLine(report);
        std::printf("%4d  %10.0f  %8.0f  %9.0f\n", s, ms, line["loop"]["frame_ms"].get<double>(),
                    line["loop"]["render_ms"].get<double>());
        if (s > 0) {  // the first frame compiles the shaders
            latencies.push_back(ms);
            frameMs += line["loop"]["frame_ms"].get<double>();
        }
    }
    std::ofstream(stop) << "done\n";
    int status = 0;
    waitpid(child, &status, 0);
    std::sort(latencies.begin(), latencies.end());
    double mean = 0.0;
    for (double ms : latencies) mean += ms / static_cast<double>(latencies.size());
    if (!latencies.empty())
        std::printf("poll %g ms, steps 1..%d: latency mean %.0f ms, median %.0f, min %.0f, max %.0f; "
                    "of the mean, the frame %.0f ms and before it (looks, read, resample) %.0f ms\n",
                    pollMs, steps - 1, mean, latencies[latencies.size() / 2], latencies.front(), latencies.back(),
                    frameMs / static_cast<double>(latencies.size()),
                    mean - frameMs / static_cast<double>(latencies.size()));
    if (keep.empty()) fs::remove_all(folder);
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 0 : 1;
}
