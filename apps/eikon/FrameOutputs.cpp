#include "apps/eikon/FrameOutputs.h"

#include "bridge/core/Error.h"
#include "io/image/ImageIo.h"

#include <vector>

namespace eikon::app {

FrameOutputs::FrameOutputs(const Scene& scene, io::OutputFolder& output)
    : root_(output.root()), output_(&output), shared_(false), exporter_(scene, output.root()) {}

FrameOutputs::FrameOutputs(const Scene& scene, const std::filesystem::path& root, io::OutputFolder* output)
    : root_(root), output_(output), shared_(true), exporter_(scene, root, /*deferIndexes=*/true) {}

void FrameOutputs::write(int frame, const render::FrameResult& result, const std::string& reportLine,
                         const render::FrameRenderer& renderer, const ExportInputs& exported) {
    const std::filesystem::path png = io::OutputFolder::framePathIn(root_, frame);
    io::writePng(png, result.image.width, result.image.height, result.image.rgba);
    if (!result.hdr.empty())
        io::writeHdr(std::filesystem::path(png).replace_extension(".hdr"), result.image.width, result.image.height,
                     result.hdr);
    if (const render::DiagnosticStage* diagnostic = renderer.diagnosticStage(); diagnostic && diagnostic->hasReference()) {
        // BOS: the background without the medium beside the picture with it (frames/reference_NNNNN.png).
        const render::Image8 reference = diagnostic->downloadReference();
        std::filesystem::path path = png;
        path.replace_filename("reference_" + png.filename().string().substr(std::string("frame_").size()));
        io::writePng(path, reference.width, reference.height, reference.rgba);
    }
    if (exporter_.wantsFrame(frame)) exporter_.write(frame, exported, renderer);
    if (shared_) held_[frame] = {exported.time, reportLine};
    else output_->appendReport(reportLine);  // last: a frame's line means all its files are in place
}

void FrameOutputs::appendReportLine(const std::string& line) {
    EIKON_CHECK_MSG(!shared_ && output_, "a report line outside the frames of a whole run");
    output_->appendReport(line);
}

void FrameOutputs::finishSharedRun(const std::map<int, HeldFrame>& frames) {
    EIKON_CHECK_MSG(shared_ && output_, "finishSharedRun on rank 0 of a shared run");
    std::map<int, double> times;
    std::vector<std::string> lines;
    for (const auto& [frame, held] : frames) {
        times[frame] = held.time;
        lines.push_back(held.reportLine);
    }
    exporter_.writeIndexes(times);
    output_->appendReports(lines);
}

}  // namespace eikon::app
