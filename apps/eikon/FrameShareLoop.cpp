#include "apps/eikon/FrameShareLoop.h"

#include "apps/common/FrameSource.h"
#include "apps/eikon/FrameExport.h"
#include "apps/eikon/FrameLoop.h"
#include "apps/eikon/FrameOutputs.h"
#include "apps/common/LatticeWarning.h"
#include "apps/eikon/ErrorWarning.h"
#include "apps/eikon/PowerWarning.h"
#include "apps/eikon/Ranks.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <optional>

namespace eikon::app {

namespace {

std::string heldFramesText(const std::map<int, HeldFrame>& frames) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& [frame, held] : frames) list.push_back({frame, held.time, held.reportLine});
    return list.dump();
}

void addHeldFrames(const std::string& text, std::map<int, HeldFrame>& frames) {
    for (const auto& entry : nlohmann::json::parse(text))
        frames[entry.at(0).get<int>()] = {entry.at(1).get<double>(), entry.at(2).get<std::string>()};
}

}  // namespace

void renderFrameShare(const Scene& scene, sim::SceneFields& fields, int frames,
                      const std::function<io::OutputFolder&()>& openOutput, ProgressBar& progress,
                      const std::filesystem::path& outputRoot) {
    Ranks& ranks = Ranks::world();
    FrameSource source(scene, fields, rendererOptionsFor(scene), /*pipelined=*/false, ExportNeeds(scene.exports));
    std::optional<io::OutputFolderShare> share;  // outlives the writers
    std::optional<FrameOutputs> outputs;
    // Rank 0 opens the folder once its frame 0 is rendered, with a journal
    // for each other rank's files; the others wait for that before they
    // write (one barrier, reached by every rank, even one without frames).
    const auto openOutputs = [&] {
        if (ranks.first()) {
            io::OutputFolder& folder = openOutput();
            folder.shareWith(ranks.size());
            outputs.emplace(scene, outputRoot, &folder);
        }
        ranks.barrier();
        if (!ranks.first()) {
            share.emplace(outputRoot, ranks.rank());
            outputs.emplace(scene, outputRoot, nullptr);
        }
    };
    const bool simulated = fields.changesOverTime();
    PowerWarning warning;
    ErrorWarning errorWarning(scene.render.warnError);
    LatticeWarning latticeWarning;
    for (int frame = ranks.rank(); frame < frames; frame += ranks.size()) {
        const auto start = std::chrono::steady_clock::now();
        if (frame > 0) source.seekFrame(frame);  // frame 0's fields are the initial ones
        const render::FrameResult result = source.render();
        const ProducedFrame& current = source.current();
        const LoopTiming timing{millisecondsSince(start), renderMilliseconds(result), 0.0};
        warning.check(frame, result);
        errorWarning.check(frame, result);
        latticeWarning.check(frame, result);
        if (!outputs) openOutputs();
        outputs->write(frame, result,
                       frameReportJson(frame, current, simulated, result, timing, false, Distribution::Frames,
                                       ranks.size()),
                       source.renderer(), {current.time, source.currentViews(), current.exportArrays, current.meshes});
        progress.advance();
    }
    if (!outputs) openOutputs();  // a rank with no frame of its own
    const std::vector<std::string> texts = ranks.gatherToFirst(heldFramesText(outputs->held()));
    if (!ranks.first()) return;
    std::map<int, HeldFrame> all;
    for (const std::string& text : texts) addHeldFrames(text, all);
    outputs->finishSharedRun(all);
}

}  // namespace eikon::app
