#include "io/files/OutputFolder.h"

#include "bridge/core/Error.h"
#include "io/files/AtomicFile.h"

#include <cstdio>

namespace eikon::io {

OutputFolder::OutputFolder(std::filesystem::path root, bool force) : root_(std::move(root)) {
    namespace fs = std::filesystem;
    if (fs::exists(root_) && !fs::is_directory(root_))
        throw InputError(root_.string(), "an output folder", "a file");
    if (fs::exists(root_) && !fs::is_empty(root_)) {
        if (!force)
            throw InputError(root_.string() +
                             ": the output folder holds an earlier run; choose another --out or pass --force to clear it");
        for (const auto& entry : fs::directory_iterator(root_)) fs::remove_all(entry.path());
    }
    fs::create_directories(root_ / "frames");
}

std::filesystem::path OutputFolder::framePath(int frame) const {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", frame);
    return root_ / "frames" / name;
}

void OutputFolder::appendReport(const std::string& jsonLine) {
    report_ += jsonLine + "\n";
    writeFileAtomically(root_ / "report.jsonl", report_);
}

}  // namespace eikon::io
