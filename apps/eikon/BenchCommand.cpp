#include "apps/eikon/BenchCommand.h"

#include "apps/eikon/BenchKernels.h"

#include "io/files/AtomicFile.h"
#include "io/scene/SceneParser.h"
#include "gl/GlContext.h"
#include "render/graph/FrameRenderer.h"
#include "render/stages/StageDevice.h"
#include "sim/SceneFields.h"

#include <nlohmann/json.hpp>

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace eikon::app {

namespace {

struct Measurement {
    std::string name;
    double medianMs = 0.0;
    render::PhotonStats stats;
    std::string device;  // of the photon stage, as the frame report names it
};

// Median wall time of `repeats` relights after one full frame (compilation,
// upload, prepare and step structure are not timed).
Measurement measure(const std::string& name, const Scene& scene, const FieldSet& fields,
                    render::RendererOptions options, int repeats) {
    options.tracePhotons = true;
    render::FrameRenderer renderer(scene, fields, options);
    Measurement measurement{name, 0.0, {}, ""};
    for (const render::StageReport& stage : renderer.render(fields).stages)
        if (stage.name == "photons") measurement.device = render::stageDeviceName(stage.device);
    std::vector<double> times;
    for (int i = 0; i < repeats; ++i) times.push_back(renderer.relight(measurement.stats).milliseconds);
    measurement.medianMs = median(times);
    return measurement;
}

// Median view + post time of camera-only frames: the camera orbits the
// target a little each frame, so only those two stages run.
double measureCameraFrames(const Scene& scene, const FieldSet& fields, int repeats, double& postMs) {
    render::FrameRenderer renderer(scene, fields);
    renderer.render(fields);
    std::vector<double> view, post;
    CameraDesc camera = scene.camera;
    for (int i = 0; i < repeats; ++i) {
        const glm::dvec3 offset = camera.position - camera.target;
        const double angle = 0.05;  // radians about +y
        camera.position = camera.target + glm::dvec3(std::cos(angle) * offset.x + std::sin(angle) * offset.z, offset.y,
                                                     -std::sin(angle) * offset.x + std::cos(angle) * offset.z);
        renderer.setCamera(camera);
        for (const auto& stage : renderer.render(fields).stages) {
            if (stage.name == "view") view.push_back(stage.milliseconds);
            if (stage.name == "post") post.push_back(stage.milliseconds);
        }
    }
    postMs = median(post);
    return median(view);
}

}  // namespace

void addBenchCommand(CLI::App& app, BenchOptions& options) {
    CLI::App* bench = app.add_subcommand("bench", "Measure photon-tracer throughput (steps/s, deposits/s, ms per relight)");
    bench->add_option("scene", options.scenePath, "Scene file (default: scenes/default.json)");
    bench->add_option("--resolution", options.resolution, "Grid cells per axis")->check(CLI::Range(4, 512));
    bench->add_option("--photons", options.photons, "Photons per relight")->check(CLI::Range(1LL, 2147483647LL));
    bench->add_option("--repeats", options.repeats, "Timed relights; the median is reported")->check(CLI::Range(1, 1000));
    bench->add_option("--set", options.overrides, "Override a scene value")->type_name("KEY.PATH=VALUE");
    bench->add_option("--out", options.outFile, "Also write the figures as JSON to this file");
}

int benchCommand(const BenchOptions& options) {
    std::vector<std::string> overrides = options.overrides;
    const std::string r = std::to_string(options.resolution);
    overrides.push_back("grid.resolution=[" + r + "," + r + "," + r + "]");
    overrides.push_back("render.photons=" + std::to_string(options.photons));
    const Scene scene = loadSceneFile(options.scenePath, overrides);
    Scene storing = scene;
    storing.tracer.storeFluence = true;
    const sim::SceneFields sceneFields(scene);  // validates the fields
    const FieldSet& fields = sceneFields.fields();
    const auto context = gl::createHeadlessContext();

    // The wavefront has no bare march to compare with.
    const bool byWavefront = scene.tracer.estimator == TracerDesc::Estimator::Wavefront;
    std::vector<Measurement> measurements = {measure("tracer", scene, fields, {}, options.repeats),
                                             measure("tracer+fluence", storing, fields, {}, options.repeats)};
    if (!byWavefront)
        measurements.push_back(measure("bare march", scene, fields, {.photons = {.bareMarch = true}}, options.repeats));
    nlohmann::json summary = {{"scene", options.scenePath},
                              {"resolution", options.resolution},
                              {"photons", options.photons},
                              {"renderer", context->info().renderer},
                              {"runs", nlohmann::json::array()}};
    if (byWavefront)
        std::printf("%s, %d^3, wavefront estimator, on %s\n", options.scenePath.c_str(), options.resolution,
                    context->info().renderer.c_str());
    else
        std::printf("%s, %d^3, %lld photons, on %s\n", options.scenePath.c_str(), options.resolution, options.photons,
                    context->info().renderer.c_str());
    std::printf("%-16s %12s %14s %16s %18s\n", "kernel", "ms/relight", "steps", "M steps/s", "M deposits/s");
    for (const auto& m : measurements) {
        const double seconds = m.medianMs / 1000.0;
        const double stepsPerSecond = static_cast<double>(m.stats.steps) / seconds;
        const double depositsPerSecond = static_cast<double>(m.stats.voxelDeposits) / seconds;
        std::printf("%-16s %12.1f %14llu %16.1f %18.1f\n", m.name.c_str(), m.medianMs,
                    static_cast<unsigned long long>(m.stats.steps), stepsPerSecond / 1e6, depositsPerSecond / 1e6);
        summary["runs"].push_back({{"kernel", m.name},
                                   {"ms_per_relight", m.medianMs},
                                   {"steps", m.stats.steps},
                                   {"voxel_deposits", m.stats.voxelDeposits},
                                   {"steps_per_second", stepsPerSecond},
                                   {"deposits_per_second", depositsPerSecond}});
    }
    if (byWavefront) {
        for (const Measurement& m : measurements) {
            const render::WavefrontCounts& w = m.stats.wavefront;
            std::printf("%s wavefront: %llu patches (%llu at the limit), %llu splits, %llu rays, %llu tubes\n",
                        m.name.c_str(), static_cast<unsigned long long>(w.patches),
                        static_cast<unsigned long long>(w.atLimit), static_cast<unsigned long long>(w.splits),
                        static_cast<unsigned long long>(w.rays), static_cast<unsigned long long>(w.tubes));
            summary["wavefront"][m.name] = {{"patches", w.patches}, {"patches_at_limit", w.atLimit},
                                            {"splits", w.splits}, {"rays", w.rays}, {"tubes", w.tubes}};
        }
    } else {
        const double ratio = static_cast<double>(measurements[0].stats.steps) / measurements[0].medianMs /
                             (static_cast<double>(measurements[2].stats.steps) / measurements[2].medianMs);
        std::printf("tracer step rate / bare march step rate = %.2f\n", ratio);
        summary["tracer_over_bare_march_step_rate"] = ratio;
    }
    double postMs = 0.0;
    const double viewMs = measureCameraFrames(scene, fields, options.repeats, postMs);
    std::printf("camera-only frame at %dx%d: view %.1f ms, post %.1f ms\n", scene.render.width, scene.render.height,
                viewMs, postMs);
    summary["camera_only_view_ms"] = viewMs;
    summary["camera_only_post_ms"] = postMs;
    std::vector<KernelFigure> kernels = measureKernels(scene, fields, options.repeats);
    const bool storedEitherWay = scene.tracer.storeFluence || fields.hasScattering();
    kernels.push_back(fluenceFigure(static_cast<std::uint64_t>(scene.grid.spec().cellCount()), storedEitherWay,
                                    {measurements[1].medianMs, measurements[1].device},
                                    {measurements[0].medianMs, measurements[0].device}));
    std::printf("per kernel, median of %d frames with every field new (fluence: tracer+fluence - tracer):\n",
                options.repeats);
    printKernels(kernels);
    summary["kernels"] = kernelsJson(kernels);
    if (!options.outFile.empty()) io::writeFileAtomically(options.outFile, summary.dump(2) + "\n");
    return 0;
}

}  // namespace eikon::app
