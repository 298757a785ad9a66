#include "apps/eikon/FrameLoop.h"

#include "bridge/grid/FieldViews.h"
#include "bridge/io/ImageIo.h"
#include "bridge/io/vtk/VtkSeriesWriter.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <memory>
#include <optional>

namespace eikon::app {

namespace {

nlohmann::json rgbJson(const Rgb& rgb) { return {rgb.r, rgb.g, rgb.b}; }

nlohmann::json photonsJson(const render::PhotonStats& p) {
    return {{"power_w",
             {{"emitted", rgbJson(p.emitted)},
              {"absorbed", rgbJson(p.absorbed)},
              {"escaped", rgbJson(p.escaped)},
              {"received", rgbJson(p.received)},
              {"cut_off", rgbJson(p.cutOff)},
              {"blocked", rgbJson(p.blocked)},
              {"reflected", rgbJson(p.reflected)}}},
            {"count",
             {{"escaped", p.photonsEscaped},
              {"received", p.photonsReceived},
              {"cut_off", p.photonsCutOff},
              {"blocked", p.photonsBlocked}}},
            {"emitted", p.photons},
            {"energy_balance_error", p.balanceError()},
            {"steps", p.steps},
            {"mean_steps_per_photon",
             p.photons > 0 ? static_cast<double>(p.steps) / static_cast<double>(p.photons) : 0.0},
            {"voxel_deposits", p.voxelDeposits},
            {"max_invariant_error", p.maxInvariantError},
            {"mean_invariant_error", p.meanInvariantError}};
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

double renderMilliseconds(const render::FrameResult& result) {
    double ms = 0.0;
    for (const auto& stage : result.stages) ms += stage.milliseconds;
    return ms;
}

// Writes frame `frame`'s image, HDR, report line and (optionally) VTK fields.
class FrameOutputs {
public:
    FrameOutputs(io::OutputFolder& output, bool exportVtk) : output_(output) {
        if (exportVtk) vtk_.emplace(output.root(), "fields");
    }

    void write(int frame, const render::FrameResult& result, const std::string& reportLine,
               const render::FrameRenderer& renderer, double time, const ConstFieldViews& fields) {
        io::writePng(output_.framePath(frame), result.image.width, result.image.height, result.image.rgba);
        if (!result.hdr.empty())
            io::writeHdr(output_.framePath(frame).replace_extension(".hdr"), result.image.width, result.image.height,
                         result.hdr);
        output_.appendReport(reportLine);
        if (vtk_) {
            std::vector<io::NamedArray> extra;
            if (const render::PhotonStage* photons = renderer.photonStage(); photons && photons->storesFluence())
                extra.push_back({"fluence", 3, photons->downloadFluence()});
            vtk_->writeFrame(frame, time, copyToFieldSet(fields), extra);
        }
    }

private:
    io::OutputFolder& output_;
    std::optional<io::VtkSeriesWriter> vtk_;
};

// Fields in host memory: a static scene (uploaded once), or one whose mesh
// and water objects move without a fluid solver (SceneFields recomputes the
// cells they touched; the changed fields are uploaded).
void runHostFrames(const Scene& scene, sim::SceneFields& fields, int frames, FrameOutputs& outputs,
                   ProgressBar& progress) {
    render::FrameRenderer renderer(scene, fields.fields());
    const bool animated = fields.changesOverTime();
    for (int frame = 0; frame < frames; ++frame) {
        const auto start = std::chrono::steady_clock::now();
        ProducedFrame produced;
        if (frame > 0 && animated) {
            fields.advanceFrame();
            produced.simulated = true;
            produced.simulateMs = millisecondsSince(start);
        }
        produced.time = fields.time();
        produced.phases = fields.lastTimings();
        const render::FrameResult result = renderer.render(fields.fields());
        const LoopTiming timing{millisecondsSince(start), renderMilliseconds(result), 0.0};
        outputs.write(frame, result, frameReportJson(frame, produced, animated, result, timing, false), renderer,
                      produced.time, viewsOf(fields.fields()));
        progress.advance();
    }
}

void runLiveFrames(const Scene& scene, sim::SceneFields& fields, int frames, FrameOutputs& outputs,
                   ProgressBar& progress, bool pipelined) {
    LiveFrames live(fields, pipelined);
    render::FrameRenderer renderer(scene, live.ring());
    for (int frame = 0; frame < frames; ++frame) {
        const auto start = std::chrono::steady_clock::now();
        const bool more = frame + 1 < frames;
        if (more) live.beginNext();
        const render::FrameResult result = renderer.render(live.ring());
        LoopTiming timing{0.0, renderMilliseconds(result), 0.0};
        if (more) {
            const ProducedFrame& next = live.waitNext();
            timing.produceNextMs = next.simulateMs + next.writeFieldsMs;
        }
        timing.frameMs = millisecondsSince(start);
        const ProducedFrame& current = live.current();
        outputs.write(frame, result, frameReportJson(frame, current, true, result, timing, pipelined), renderer,
                      current.time, live.ring().currentViews());
        if (more) live.publishNext();  // frame k's slot stays current until its outputs are written
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

void runFrames(const Scene& scene, sim::SceneFields& fields, int frames, io::OutputFolder& output,
               ProgressBar& progress, const LoopOptions& options) {
    FrameOutputs outputs(output, options.exportVtk);
    if (fields.simulatesFluid()) runLiveFrames(scene, fields, frames, outputs, progress, options.pipelined);
    else runHostFrames(scene, fields, frames, outputs, progress);
    progress.finish();
}

}  // namespace eikon::app
