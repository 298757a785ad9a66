#include "apps/eikon/FrameLoop.h"

#include "apps/eikon/FrameExport.h"
#include "bridge/grid/FieldViews.h"
#include "bridge/io/ImageIo.h"

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

// Writes frame `frame`'s image, HDR and report line, and what the scene's
// `export` section asks of it.
class FrameOutputs {
public:
    FrameOutputs(const Scene& scene, io::OutputFolder& output) : output_(output), exporter_(scene, output.root()) {}

    bool exportsFrame(int frame) const { return exporter_.wantsFrame(frame); }

    // `exported` is read only when exportsFrame(frame).
    void write(int frame, const render::FrameResult& result, const std::string& reportLine,
               const render::FrameRenderer& renderer, const ExportInputs& exported) {
        io::writePng(output_.framePath(frame), result.image.width, result.image.height, result.image.rgba);
        if (!result.hdr.empty())
            io::writeHdr(output_.framePath(frame).replace_extension(".hdr"), result.image.width, result.image.height,
                         result.hdr);
        output_.appendReport(reportLine);
        if (exporter_.wantsFrame(frame)) exporter_.write(frame, exported, renderer);
    }

private:
    io::OutputFolder& output_;
    FrameExporter exporter_;
};

// Fields in host memory: a static scene (uploaded once), or one whose mesh
// and water objects move without a fluid solver (SceneFields recomputes the
// cells they touched; the changed fields are uploaded).
void runHostFrames(const Scene& scene, sim::SceneFields& fields, int frames, FrameOutputs& outputs,
                   ProgressBar& progress) {
    render::FrameRenderer renderer(scene, fields.fields(), rendererOptionsFor(scene));
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
        ExportInputs exported{produced.time, viewsOf(fields.fields()), {}, {}};
        if (outputs.exportsFrame(frame)) {
            exported.simulation = fields.exportArrays();
            for (const TriangleMesh* mesh : fields.deformedMeshes()) exported.meshes.push_back(*mesh);
        }
        outputs.write(frame, result, frameReportJson(frame, produced, animated, result, timing, false), renderer,
                      exported);
        progress.advance();
    }
}

void runLiveFrames(const Scene& scene, sim::SceneFields& fields, int frames, FrameOutputs& outputs,
                   ProgressBar& progress, bool pipelined) {
    LiveFrames live(fields, pipelined, scene.exports.vtk.enabled || scene.exports.vdb.enabled);
    render::FrameRenderer renderer(scene, live.ring(), rendererOptionsFor(scene));
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
                      {current.time, live.ring().currentViews(), current.exportArrays, current.meshes});
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
    FrameOutputs outputs(scene, output);
    if (fields.simulatesFluid()) runLiveFrames(scene, fields, frames, outputs, progress, options.pipelined);
    else runHostFrames(scene, fields, frames, outputs, progress);
    progress.finish();
}

}  // namespace eikon::app
