#include "apps/eikon/BenchKernels.h"

#include "render/graph/FrameRenderer.h"
#include "render/stages/StageDevice.h"

#include <algorithm>
#include <cstdio>
#include <map>

namespace eikon::app {

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

namespace {

// What one stage worked on in a frame, unit by unit.
std::vector<std::pair<std::string, std::uint64_t>> unitsOf(const std::string& stage, const Scene& scene,
                                                           const render::FrameResult& frame) {
    const auto cells = static_cast<std::uint64_t>(scene.grid.spec().cellCount());
    const auto pixels =
        static_cast<std::uint64_t>(scene.render.width) * static_cast<std::uint64_t>(scene.render.height);
    const render::PhotonStats& photons = frame.photons;
    if (stage == "prepare" || stage == "step_structure" || stage == "reference_steps" ||
        stage == "multiple_scattering")
        return {{"cell", cells}};
    if (stage == "photons" && photons.byWavefront)
        return {{"ray", photons.wavefront.rays}, {"patch", photons.wavefront.patches}, {"step", photons.steps}};
    if (stage == "photons")
        return {{"photon", static_cast<std::uint64_t>(photons.photons)}, {"step", photons.steps}};
    if (stage == "view")
        return {{"camera ray", pixels * static_cast<std::uint64_t>(scene.render.samplesPerPixel)}};
    if (stage == "post") return {{"pixel", pixels}};
    if (stage == "upload") return {{"byte", frame.copied.host + frame.copied.gpu}};
    return {{"frame", 1}};
}

}  // namespace

std::vector<KernelFigure> measureKernels(const Scene& scene, const FieldSet& fields, int repeats) {
    render::RendererOptions options;
    options.tracePhotons = true;
    render::FrameRenderer renderer(scene, fields, options);
    FieldSet frame = fields;
    renderer.render(frame);
    std::map<std::string, std::vector<double>> times;
    render::FrameResult last;
    for (int i = 0; i < repeats; ++i) {
        // New versions: the renderer takes every field as changed.
#define EIKON_NEW_VERSION(group) ++frame.group##Version;
        EIKON_OPTICAL_FIELD_VERSIONS(EIKON_NEW_VERSION)
#undef EIKON_NEW_VERSION
        last = renderer.render(frame);
        for (const render::StageReport& stage : last.stages) times[stage.name].push_back(stage.milliseconds);
    }
    std::vector<KernelFigure> figures;
    for (const render::StageReport& stage : last.stages)
        for (const auto& [unit, count] : unitsOf(stage.name, scene, last))
            figures.push_back({stage.name, unit, render::stageDeviceName(stage.device), count,
                               median(times[stage.name]), stage.ran,
                               stage.ran ? "" : "not run: " + stage.skippedBecause});
    return figures;
}

KernelFigure fluenceFigure(std::uint64_t cells, bool storedEitherWay, const Relight& withFluence,
                           const Relight& withoutFluence) {
    const double difference = withFluence.milliseconds - withoutFluence.milliseconds;
    KernelFigure figure{"fluence", "cell", withFluence.device, cells, difference, true, ""};
    char text[200];
    if (storedEitherWay) {
        figure.measured = false;
        figure.reason = "the scene stores fluence with or without tracer.store_fluence (it scatters, or sets it)";
    } else if (withFluence.device != withoutFluence.device) {
        std::snprintf(text, sizeof text, "not measured: the photon pass ran on %s with fluence, on %s without it",
                      withFluence.device.c_str(), withoutFluence.device.c_str());
        figure.measured = false;
        figure.reason = text;
    } else if (difference <= 0.0) {
        std::snprintf(text, sizeof text, "not resolved: the relight with fluence took %.2f ms, without it %.2f ms",
                      withFluence.milliseconds, withoutFluence.milliseconds);
        figure.measured = false;
        figure.reason = text;
    }
    return figure;
}

void printKernels(const std::vector<KernelFigure>& figures) {
    std::printf("%-20s %-11s %-6s %14s %12s %14s\n", "kernel", "unit", "device", "count", "ms", "ns/unit");
    for (const KernelFigure& figure : figures) {
        if (figure.measured)
            std::printf("%-20s %-11s %-6s %14llu %12.2f %14.2f\n", figure.kernel.c_str(), figure.unit.c_str(),
                        figure.device.c_str(), static_cast<unsigned long long>(figure.count), figure.milliseconds,
                        figure.nanosecondsPerUnit());
        else
            std::printf("%-20s %-11s %-6s %14llu %12.2f   %s\n", figure.kernel.c_str(), figure.unit.c_str(),
                        figure.device.c_str(), static_cast<unsigned long long>(figure.count), figure.milliseconds,
                        figure.reason.c_str());
    }
}

nlohmann::json kernelsJson(const std::vector<KernelFigure>& figures) {
    nlohmann::json rows = nlohmann::json::array();
    for (const KernelFigure& figure : figures) {
        nlohmann::json row = {{"kernel", figure.kernel}, {"unit", figure.unit}, {"count", figure.count},
                              {"ms", figure.milliseconds}, {"measured", figure.measured}};
        if (!figure.device.empty()) row["device"] = figure.device;
        if (figure.measured)
            row["ns_per_unit"] = figure.nanosecondsPerUnit();
        else
            row["reason"] = figure.reason;
        rows.push_back(row);
    }
    return rows;
}

}  // namespace eikon::app
