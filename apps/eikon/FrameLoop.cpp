#include "apps/eikon/FrameLoop.h"

#include "apps/eikon/FrameExport.h"
#include "bridge/io/ImageIo.h"

#include <nlohmann/json.hpp>

namespace eikon::app {

namespace {

nlohmann::json rgbJson(const Rgb& rgb) { return {rgb.r, rgb.g, rgb.b}; }

}  // namespace

std::string frameReportJson(int frame, const sim::SceneFields& fields, const render::FrameResult& result) {
    nlohmann::json stages = nlohmann::json::array();
    for (const auto& stage : result.stages)
        stages.push_back({{"name", stage.name}, {"ran", stage.ran}, {"ms", stage.milliseconds}});
    const render::PhotonStats& p = result.photons;
    nlohmann::json photons = {
        {"power_w",
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
        {"mean_steps_per_photon", p.photons > 0 ? static_cast<double>(p.steps) / static_cast<double>(p.photons) : 0.0},
        {"voxel_deposits", p.voxelDeposits},
        {"max_invariant_error", p.maxInvariantError},
        {"mean_invariant_error", p.meanInvariantError}};
    nlohmann::json report{{"frame", frame},
                          {"time_s", fields.time()},
                          {"stages", stages},
                          {"host_bytes_uploaded", result.hostBytesUploaded},
                          {"photons", photons}};
    if (fields.changesOverTime()) {
        nlohmann::json phases = nlohmann::json::array();
        for (const auto& phase : fields.lastTimings())
            phases.push_back({{"phase", phase.phase},
                              {"ms", phase.milliseconds},
                              {"iterations", phase.iterations},
                              {"residual", phase.residual}});
        report["simulation"] = phases;
    }
    return report.dump();
}

void runFrames(const Scene& scene, sim::SceneFields& fields, int frames, io::OutputFolder& output,
               ProgressBar& progress) {
    render::FrameRenderer renderer(scene, fields.fields(), rendererOptionsFor(scene));
    FrameExporter exporter(scene, output.root());
    for (int frame = 0; frame < frames; ++frame) {
        if (frame > 0) fields.advanceFrame();
        const render::FrameResult result = renderer.render(fields.fields());
        io::writePng(output.framePath(frame), result.image.width, result.image.height, result.image.rgba);
        if (!result.hdr.empty())
            io::writeHdr(output.framePath(frame).replace_extension(".hdr"), result.image.width, result.image.height,
                         result.hdr);
        output.appendReport(frameReportJson(frame, fields, result));
        if (exporter.wantsFrame(frame)) exporter.write(frame, fields, renderer);
        progress.advance();
    }
    progress.finish();
}

}  // namespace eikon::app
