// The output folder of a run: DIR/frames/frame_NNNNN.png, DIR/report.jsonl
// and whatever the exporters add. DIR/.eikon-run lists every file the run
// wrote, kept up to date after each frame. A folder that already holds files
// is refused — with `force`, one holding an earlier run is cleared of the
// files its list names and of the temporaries a killed run was writing
// (NAME.tmpPID of eikon's own file names; nothing else is touched), so the frames of two runs
// never mix and nothing eikon did not write is ever deleted; a folder without
// that list is refused even with `force`.
#pragma once

#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace eikon::io {

class OutputFolder {
public:
    // Throws InputError (exit code 2) when `root` is a file, holds files eikon
    // did not write, or holds an earlier run and !force. withFrames: with
    // its frames/ folder (`eikon converge` writes no frames).
    OutputFolder(std::filesystem::path root, bool force, bool withFrames = true);
    // The same refusals, without touching the folder: for a run that
    // checks everything before it writes anything.
    static void requireUsable(const std::filesystem::path& root, bool force);
    ~OutputFolder();

    const std::filesystem::path& root() const { return root_; }
    std::filesystem::path framePath(int frame) const { return framePathIn(root_, frame); }
    // DIR/frames/frame_NNNNN.png of the folder `root` (for the processes of a
    // run that write frames into a folder another one opened).
    static std::filesystem::path framePathIn(const std::filesystem::path& root, int frame);

    // Appends one JSON line to report.jsonl, rewriting the file atomically so
    // a reader never sees half a line, and brings the list of written files
    // up to date.
    void appendReport(const std::string& jsonLine);
    // The same for several lines at once, in order (one rewrite).
    void appendReports(const std::vector<std::string>& jsonLines);
    // Rewrites DIR/.eikon-run with every file now in the folder that was not
    // there when the run began.
    void recordWrittenFiles() const;

    static constexpr const char* kManifestName = ".eikon-run";

private:
    std::filesystem::path root_;
    std::set<std::filesystem::path> before_;  // files left in the folder when the run began (relative)
    std::string report_;
};

}  // namespace eikon::io
