// Writes each frame's image (PNG, and HDR when the scene asks), what the
// scene's `export` section selects of it, and its line of report.jsonl —
// last, so that a frame's line means all its files are in place.
//
// Where the ranks of an MPI job share a run's frames (`--distribute
// frames`), each writes its frames' files into the folder rank 0 opened and
// holds its report lines back; rank 0 appends every rank's lines, in frame
// order, and writes the series indexes (.pvd, .series) once all frames exist.
#pragma once

#include "apps/eikon/FrameExport.h"
#include "bridge/scene/Scene.h"
#include "io/files/OutputFolder.h"
#include "render/graph/FrameRenderer.h"

#include <filesystem>
#include <map>
#include <string>

namespace eikon::app {

struct HeldFrame {
    double time = 0.0;
    std::string reportLine;
};

class FrameOutputs {
public:
    // A whole run, into the folder it opened.
    FrameOutputs(const Scene& scene, io::OutputFolder& output);
    // A share of a run's frames, into the folder `root`: rank 0 passes the
    // folder it opened, the other ranks null.
    FrameOutputs(const Scene& scene, const std::filesystem::path& root, io::OutputFolder* output);

    // `exported` is read only when the scene exports this frame.
    void write(int frame, const render::FrameResult& result, const std::string& reportLine,
               const render::FrameRenderer& renderer, const ExportInputs& exported);

    // A line of report.jsonl that is not a frame's (a followed run's end, FollowReport.h).
    void appendReportLine(const std::string& line);

    // A share's frames written so far, by number.
    const std::map<int, HeldFrame>& held() const { return held_; }
    // Rank 0, once every rank's frames exist: their report lines and the
    // series indexes.
    void finishSharedRun(const std::map<int, HeldFrame>& frames);

private:
    std::filesystem::path root_;
    io::OutputFolder* output_;  // null on a rank that writes into another's folder
    bool shared_;
    FrameExporter exporter_;
    std::map<int, HeldFrame> held_;
};

}  // namespace eikon::app
