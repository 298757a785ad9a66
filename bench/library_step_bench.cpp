// The library's cost per step (docs/library.md): a 64³ temperature field
// handed to eikon::Renderer every step, against the built-in path that
// maps the same samples (a volume file's frame, SceneFields'
// writeCallerFields) and renders them. What the library adds is its check
// of the caller's arrays (library::takeFields: shape, box, finite values)
// and the report; the mapping and the render are the built-in path's.
//   bench_library_step [steps]
#include "eikon/eikon.h"

#include "apps/library/FieldIntake.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

constexpr int kN = 64;

const char* const kScene = R"({
  "grid": {"bounds": {"min": [-0.2, 0.0, -0.2], "max": [0.2, 0.4, 0.2]}, "resolution": [64, 64, 64]},
  "lights": [{"type": "directional", "direction": [0, -1, 0], "irradiance": [1, 1, 1]}],
  "camera": {"position": [0.0, 0.25, 2.5], "target": [0.0, -0.5, -3.0], "fov_deg": 6},
  "render": {"width": 320, "height": 240,
             "environment": {"type": "sky", "ground_height": -1.0, "checker_size": 0.03,
                             "ground_a": [0.85, 0.85, 0.8], "ground_b": [0.05, 0.05, 0.06]}}
})";

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
    const int steps = argc > 1 ? std::stoi(argv[1]) : 20;
    eikon::Renderer renderer = eikon::Renderer::fromJson(kScene);
    const eikon::Grid grid = renderer.grid();
    std::vector<float> temperature(static_cast<std::size_t>(kN) * kN * kN);
    const eikon::Field field{"temperature", temperature.data(), {kN, kN, kN}, 1, grid.boundsMin, grid.boundsMax};
    eikon::GridSpec spec;
    spec.resolution = glm::ivec3(kN);
    spec.boundsMin = {grid.boundsMin[0], grid.boundsMin[1], grid.boundsMin[2]};
    spec.boundsMax = {grid.boundsMax[0], grid.boundsMax[1], grid.boundsMax[2]};

    std::vector<double> check, setFields, render, stages, upload, frame;
    for (int step = 0; step < steps; ++step) {
        const double centre = 0.1 + 0.01 * step;  // a warm bubble rising 1 cm a step
        for (int k = 0; k < kN; ++k)
            for (int j = 0; j < kN; ++j)
                for (int i = 0; i < kN; ++i) {
                    const double h = 0.4 / kN, x = -0.2 + (i + 0.5) * h, y = (j + 0.5) * h, z = -0.2 + (k + 0.5) * h;
                    temperature[(static_cast<std::size_t>(k) * kN + j) * kN + i] = static_cast<float>(
                        60.0 * std::exp(-(x * x + (y - centre) * (y - centre) + z * z) / 0.0036));
                }
        auto start = std::chrono::steady_clock::now();
        const eikon::library::FieldIntake intake = eikon::library::takeFields({field}, spec);
        check.push_back(msSince(start));
        start = std::chrono::steady_clock::now();
        renderer.setFields({field});
        setFields.push_back(msSince(start));
        start = std::chrono::steady_clock::now();
        renderer.render();
        render.push_back(msSince(start));
        const nlohmann::json report = nlohmann::json::parse(renderer.report());
        double stageMs = 0.0;
        for (const auto& stage : report.at("stages")) {
            stageMs += stage.at("ms").get<double>();
            if (stage.at("name") == "upload") upload.push_back(stage.at("ms").get<double>());
        }
        stages.push_back(stageMs);
        frame.push_back(report.at("loop").at("frame_ms").get<double>());
        if (intake.copiedBytes != 0 || report.at("caller_fields").at("host_bytes_copied").get<std::uint64_t>() != 0)
            std::printf("unexpected copy of the caller's field\n");
    }
    std::printf("64^3 temperature, %d steps, medians in ms:\n", steps);
    std::printf("  library check of the field (takeFields)     %8.3f\n", median(check));
    std::printf("  setFields (check + optics + objects)        %8.3f\n", median(setFields));
    std::printf("  render() wall                               %8.3f\n", median(render));
    std::printf("  the renderer's stages (report)              %8.3f\n", median(stages));
    std::printf("  of which upload                             %8.3f\n", upload.empty() ? 0.0 : median(upload));
    std::printf("  render() beyond its stages (report, loop)   %8.3f\n", median(render) - median(stages));
    // render() = the frame source's render (its stages and what runs
    // between them, as in eikon run) + the report, eikon run's line with
    // the caller's fields added (the library's part).
    std::vector<double> between, after;
    for (std::size_t s = 0; s < render.size(); ++s) {
        between.push_back(frame[s] - stages[s]);
        after.push_back(render[s] - frame[s]);
    }
    std::printf("    between the stages (eikon run's frame)    %8.3f\n", median(between));
    std::printf("    after the frame: the report               %8.3f\n", median(after));
    std::printf("  the library's own per step (check + report) %8.3f\n", median(check) + median(after));
    return 0;
}
