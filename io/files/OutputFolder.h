// The output folder of a run: DIR/frames/frame_NNNNN.png and DIR/report.jsonl.
// A folder that already holds files is refused unless `force`, which empties
// it first, so the frames of two runs never mix.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace eikon::io {

class OutputFolder {
public:
    // Throws InputError (exit code 2) when `root` is a non-empty folder and
    // !force, or is a file.
    OutputFolder(std::filesystem::path root, bool force);

    const std::filesystem::path& root() const { return root_; }
    std::filesystem::path framePath(int frame) const;

    // Appends one JSON line to report.jsonl, rewriting the file atomically so
    // a reader never sees half a line.
    void appendReport(const std::string& jsonLine);

private:
    std::filesystem::path root_;
    std::string report_;
};

}  // namespace eikon::io
