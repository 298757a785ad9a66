#include "apps/eikon/FrameLoop.h"

#include "apps/common/FrameSource.h"
#include "apps/common/LatticeWarning.h"
#include "apps/common/WavefrontCostWarning.h"
#include "apps/eikon/ErrorWarning.h"
#include "apps/eikon/FrameOutputs.h"
#include "apps/eikon/FrameShareLoop.h"
#include "apps/eikon/FluidWarning.h"
#include "apps/eikon/FollowReport.h"
#include "apps/eikon/PowerWarning.h"
#include "apps/eikon/Ranks.h"
#include "bridge/grid/FieldViews.h"
#include "bridge/scene/ImageSpaceScope.h"

#include <chrono>
#include <iostream>
#include <memory>
#include <optional>

namespace eikon::app {

namespace {

// Each turn renders the current frame and, while more follow, produces the
// next (FrameSource.h). The host fields' frame time includes the advance
// that produced the frame, as the ring's includes nothing of the next one's
// production but what the render did not hide.
void renderFrames(const Scene& scene, sim::SceneFields& fields, int frames, const OpenOutput& openOutput,
                  ProgressBar& progress, const LoopOptions& options) {
    render::RendererOptions rendererOptions = rendererOptionsFor(scene);
    Ranks& ranks = Ranks::world();
    // Sharing the light pass: every rank simulates the same fields, traces
    // its share of the photons, and rank 0 draws and writes the frame.
    const bool writes = options.distribution != Distribution::Photons || ranks.first();
    if (options.distribution == Distribution::Photons) {
        rendererOptions.share = {static_cast<unsigned>(ranks.rank()), static_cast<unsigned>(ranks.size())};
        rendererOptions.exchange = &ranks.lightPassExchange();
        rendererOptions.drawsImage = ranks.first();
    }
    const bool pipelined = options.pipelined;
    FrameSource source(scene, fields, rendererOptions, pipelined,
                       writes ? ExportNeeds(scene.exports) : ExportNeeds());
    std::optional<FrameOutputs> outputs;  // opened once frame 0 is rendered: its GPU resources all fit
    const bool simulated = fields.changesOverTime();
    PowerWarning warning;
    ErrorWarning errorWarning(scene.render.warnError);
    LatticeWarning latticeWarning;
    FluidWarning fluidWarning;
    sim::VolumeSequence* followed = fields.followedVolume();
    int rendered = 0;
    for (int frame = 0; frame < frames; ++frame) {
        const auto start = std::chrono::steady_clock::now();
        bool more = frame + 1 < frames;
        if (more) source.beginNext();
        const render::FrameResult result = source.render();
        LoopTiming timing{0.0, renderMilliseconds(result), 0.0};
        if (more && source.throughRing()) {
            const ProducedFrame& next = source.waitNext();
            timing.produceNextMs = next.simulateMs + next.writeFieldsMs;
        }
        const ProducedFrame& current = source.current();
        timing.frameMs = millisecondsSince(start) + (source.throughRing() ? 0.0 : current.simulateMs);
        if (writes) {
            warning.check(frame, result);
            errorWarning.check(frame, result);
            latticeWarning.check(frame, result);
            fluidWarning.check(frame, current);
            if (!outputs) outputs.emplace(scene, openOutput());
            std::string line = frameReportJson(frame, current, simulated, result, timing,
                                               pipelined && source.throughRing(), options.distribution, ranks.size());
            if (followed) {
                warnSkipped(followed->skippedBefore());
                line = withFollowedStep(line, followed->currentFile(), followed->skippedBefore());
            }
            outputs->write(frame, result, line, source.renderer(),
                           {current.time, source.currentViews(), current.exportArrays, current.meshes});
        }
        ++rendered;
        // A followed volume's next step, once this frame's outputs are written: a
        // frame appears as soon as its step is complete.
        if (more && followed) more = followed->followNext(true);
        if (more) source.publishNext();  // frame k's fields stay current until its outputs are written
        progress.advance();
        if (!more) break;
    }
    if (followed && outputs) {
        const std::vector<sim::SkippedStep> left = followed->finishFollowing();
        warnSkipped(left);
        const std::string why = followed->followEnd();
        outputs->appendReportLine(followEndLine(why.empty() ? "frames" : why, rendered, left));
    }
}

}  // namespace

void runFrames(const Scene& scene, sim::SceneFields& fields, int frames, const OpenOutput& openOutput,
               ProgressBar& progress, const LoopOptions& options) {
    // Said once a run, by the first rank; each frame's report lists it too.
    if (Ranks::world().first() && scene.render.method == RenderDesc::Method::ImageSpace &&
        !imageSpaceOmissions(scene).empty())
        std::cerr << "eikon: warning: " << describeImageSpaceOmissions(scene) << "\n";
    if (Ranks::world().first()) warnWavefrontStart(scene, fields.fields().hasScattering());
    if (options.distribution == Distribution::Frames)
        renderFrameShare(scene, fields, frames, openOutput, progress, options.outputRoot);
    else
        renderFrames(scene, fields, frames, openOutput, progress, options);
    progress.finish();
}

}  // namespace eikon::app
