#include "apps/eikon/FrameLoop.h"

#include "apps/common/FrameSource.h"
#include "apps/eikon/FrameExport.h"
#include "bridge/grid/FieldViews.h"
#include "io/image/ImageIo.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <memory>
#include <optional>

namespace eikon::app {

namespace {

nlohmann::json rgbJson(const Rgb& rgb) { return {rgb.r, rgb.g, rgb.b}; }

nlohmann::json photonsJson(const render::PhotonStats& p) {
    nlohmann::json json = {{"estimator", p.byWavefront ? "wavefront" : "photons"},
            {"power_w",
             {{"emitted", rgbJson(p.emitted)},
              {"absorbed", rgbJson(p.absorbed)},
              {"escaped", rgbJson(p.escaped)},
              {"received", rgbJson(p.received)},
              {"cut_off", rgbJson(p.cutOff)},
              {"blocked", rgbJson(p.blocked)},
              {"reflected", rgbJson(p.reflected)},
              {"roulette_gain", rgbJson(p.rouletteGain)},
              {"unfollowed", rgbJson(p.unfollowed)}}},
            {"count",
             {{"escaped", p.photonsEscaped},
              {"received", p.photonsReceived},
              {"cut_off", p.photonsCutOff},
              {"blocked", p.photonsBlocked}}},
            {"surface_events", {{"reflected", p.surfaceReflections}, {"transmitted", p.surfaceTransmissions}}},
            {"emitted", p.photons},
            {"energy_balance_error", p.balanceError()},
            {"steps", p.steps},
            {"mean_steps_per_photon",
             p.photons > 0 ? static_cast<double>(p.steps) / static_cast<double>(p.photons) : 0.0},
            {"voxel_deposits", p.voxelDeposits},
            {"max_invariant_error", p.maxInvariantError},
            {"mean_invariant_error", p.meanInvariantError},
            {"resumed", {{"photons", p.photonsResumed}, {"dispatches", p.resumeDispatches}}}};
    if (p.byWavefront)
        json["wavefront"] = {{"patches", p.wavefront.patches},
                             {"splits", p.wavefront.splits},
                             {"patches_at_limit", p.wavefront.atLimit},
                             {"rays", p.wavefront.rays}};
    return json;
}

double renderMilliseconds(const render::FrameResult& result) {
    double ms = 0.0;
    for (const auto& stage : result.stages) ms += stage.milliseconds;
    return ms;
}

// Writes frame `frame`'s image, HDR and report line, and what the scene's
// `export` section asks of it.
class FrameOutputs {
public:
    FrameOutputs(const Scene& scene, io::OutputFolder& output) : output_(output), exporter_(scene, output.root()) {}

    // `exported` is read only when the scene exports this frame.
    void write(int frame, const render::FrameResult& result, const std::string& reportLine,
               const render::FrameRenderer& renderer, const ExportInputs& exported) {
        io::writePng(output_.framePath(frame), result.image.width, result.image.height, result.image.rgba);
        if (!result.hdr.empty())
            io::writeHdr(output_.framePath(frame).replace_extension(".hdr"), result.image.width, result.image.height,
                         result.hdr);
        if (exporter_.wantsFrame(frame)) exporter_.write(frame, exported, renderer);
        output_.appendReport(reportLine);  // last: a frame's line means all its files are in place
    }

private:
    io::OutputFolder& output_;
    FrameExporter exporter_;
};

// Says on stderr, once a run, when a frame's photons do not account for
// their power (balance error above 1e-3), or when photons stopped before
// their light was spent lose more than 0.1% of it net of the roulette's
// gain (tracer.max_steps, or a single step past llvmpipe's loop cap): the figures are then
// not what the scene would give.
class PowerWarning {
public:
    void check(int frame, const render::FrameResult& result) {
        if (warned_) return;
        const render::PhotonStats& p = result.photons;
        const double emitted = p.emitted.r + p.emitted.g + p.emitted.b;
        if (emitted <= 0.0) return;
        const Rgb lost = p.cutOff - p.rouletteGain;
        const double lostShare = (lost.r + lost.g + lost.b) / emitted;
        if (p.balanceError() > 1e-3) {
            std::cerr << "eikon: warning: frame " << frame << ": the photons' energy balance is off by "
                      << p.balanceError() << " (report.jsonl, photons); later frames are not reported here\n";
            warned_ = true;
        } else if (lostShare > 1e-3) {
            std::cerr << "eikon: warning: frame " << frame << ": " << 100.0 * lostShare
                      << "% of the emitted power was cut off with photons still in flight (tracer.max_steps, or "
                         "one step longer than the loop cap of OpenGL on the CPU); later frames are not reported "
                         "here\n";
            warned_ = true;
        }
    }

private:
    bool warned_ = false;
};

// Each turn renders the current frame and, while more follow, produces the
// next (FrameSource.h). The host fields' frame time includes the advance
// that produced the frame, as the ring's includes nothing of the next one's
// production but what the render did not hide.
void renderFrames(const Scene& scene, sim::SceneFields& fields, int frames, const OpenOutput& openOutput,
                  ProgressBar& progress, bool pipelined) {
    FrameSource source(scene, fields, rendererOptionsFor(scene), pipelined,
                       scene.exports.vtk.enabled || scene.exports.vdb.enabled);
    std::optional<FrameOutputs> outputs;  // opened once frame 0 is rendered: its GPU resources all fit
    const bool simulated = fields.changesOverTime();
    PowerWarning warning;
    for (int frame = 0; frame < frames; ++frame) {
        const auto start = std::chrono::steady_clock::now();
        const bool more = frame + 1 < frames;
        if (more) source.beginNext();
        const render::FrameResult result = source.render();
        LoopTiming timing{0.0, renderMilliseconds(result), 0.0};
        if (more && source.throughRing()) {
            const ProducedFrame& next = source.waitNext();
            timing.produceNextMs = next.simulateMs + next.writeFieldsMs;
        }
        const ProducedFrame& current = source.current();
        warning.check(frame, result);
        timing.frameMs = millisecondsSince(start) + (source.throughRing() ? 0.0 : current.simulateMs);
        if (!outputs) outputs.emplace(scene, openOutput());
        outputs->write(frame, result,
                      frameReportJson(frame, current, simulated, result, timing, pipelined && source.throughRing()),
                      source.renderer(), {current.time, source.currentViews(), current.exportArrays, current.meshes});
        if (more) source.publishNext();  // frame k's fields stay current until its outputs are written
        progress.advance();
    }
}

}  // namespace

std::string frameReportJson(int frame, const ProducedFrame& produced, bool simulated,
                            const render::FrameResult& result, const LoopTiming& timing, bool pipelined) {
    nlohmann::json stages = nlohmann::json::array();
    if (simulated) {
        stages.push_back({{"name", "simulate"}, {"ran", produced.simulated}, {"ms", produced.simulateMs}});
        stages.push_back({{"name", "write_fields"}, {"ran", true}, {"ms", produced.writeFieldsMs}});
    }
    for (const auto& stage : result.stages)
        stages.push_back({{"name", stage.name}, {"ran", stage.ran}, {"ms", stage.milliseconds}});
    nlohmann::json report{{"frame", frame},
                          {"time_s", produced.time},
                          {"stages", stages},
                          {"host_bytes_copied", result.copied.host},
                          {"gpu_bytes_copied", result.copied.gpu},
                          {"loop",
                           {{"pipelined", pipelined},
                            {"frame_ms", timing.frameMs},
                            {"render_ms", timing.renderMs},
                            {"produce_next_ms", timing.produceNextMs}}}};
    const bool tracesPhotons = std::any_of(result.stages.begin(), result.stages.end(),
                                           [](const render::StageReport& stage) { return stage.name == "photons"; });
    if (tracesPhotons) report["photons"] = photonsJson(result.photons);
    if (simulated) {
        nlohmann::json phases = nlohmann::json::array();
        for (const auto& phase : produced.phases)
            phases.push_back({{"phase", phase.phase},
                              {"ms", phase.milliseconds},
                              {"iterations", phase.iterations},
                              {"residual", phase.residual}});
        report["simulation"] = phases;
    }
    return report.dump();
}

void runFrames(const Scene& scene, sim::SceneFields& fields, int frames, const OpenOutput& openOutput,
               ProgressBar& progress, const LoopOptions& options) {
    renderFrames(scene, fields, frames, openOutput, progress, options.pipelined);
    progress.finish();
}

}  // namespace eikon::app
