#include "io/files/OutputFolder.h"

#include "bridge/core/Error.h"
#include "io/files/AtomicFile.h"

#include <cstdio>
#include <fstream>
#include <system_error>

namespace eikon::io {

namespace fs = std::filesystem;

namespace {

constexpr const char* kManifestHeader = "# files an eikon run wrote into this folder, one per line";

// Every regular file below root, relative to it.
std::set<fs::path> filesBelow(const fs::path& root) {
    std::set<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(root))
        if (entry.is_regular_file()) files.insert(fs::relative(entry.path(), root));
    return files;
}

// Removes the files an earlier run's list names — only files inside the
// folder — and then the folders that left empty; the list goes last.
void clearEarlierRun(const fs::path& root) {
    std::ifstream manifest(root / OutputFolder::kManifestName);
    std::set<fs::path> folders;
    std::string line;
    while (std::getline(manifest, line)) {
        if (line.empty() || line[0] == '#') continue;
        const fs::path relative = fs::path(line).lexically_normal();
        if (relative.is_absolute() || relative.empty() || *relative.begin() == "..") continue;
        std::error_code ignored;
        if (fs::is_regular_file(root / relative)) fs::remove(root / relative, ignored);
        for (fs::path parent = relative.parent_path(); !parent.empty(); parent = parent.parent_path()) folders.insert(parent);
    }
    manifest.close();
    for (auto folder = folders.rbegin(); folder != folders.rend(); ++folder) {  // deepest first
        std::error_code ignored;
        if (fs::is_directory(root / *folder) && fs::is_empty(root / *folder)) fs::remove(root / *folder, ignored);
    }
    fs::remove(root / OutputFolder::kManifestName);
}

}  // namespace

OutputFolder::OutputFolder(fs::path root, bool force) : root_(std::move(root)) {
    if (fs::exists(root_) && !fs::is_directory(root_))
        throw InputError(root_.string(), "an output folder", "a file");
    if (fs::exists(root_) && !fs::is_empty(root_)) {
        if (!fs::is_regular_file(root_ / kManifestName))
            throw InputError(root_.string() +
                             ": the folder holds files eikon did not write; choose another --out (--force only clears "
                             "a folder an earlier eikon run wrote)");
        if (!force)
            throw InputError(root_.string() +
                             ": the output folder holds an earlier run; choose another --out or pass --force to clear it");
        clearEarlierRun(root_);
    }
    fs::create_directories(root_ / "frames");
    before_ = filesBelow(root_);
    recordWrittenFiles();
}

OutputFolder::~OutputFolder() {
    try {
        recordWrittenFiles();
    } catch (const std::exception&) {
        // The list was kept up to date after every frame; a failure here (a
        // full disk) leaves the last one standing.
    }
}

fs::path OutputFolder::framePath(int frame) const {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", frame);
    return root_ / "frames" / name;
}

void OutputFolder::appendReport(const std::string& jsonLine) {
    report_ += jsonLine + "\n";
    writeFileAtomically(root_ / "report.jsonl", report_);
    recordWrittenFiles();
}

void OutputFolder::recordWrittenFiles() const {
    std::string list = std::string(kManifestHeader) + "\n";
    for (const fs::path& file : filesBelow(root_))
        if (file != kManifestName && !before_.count(file)) list += file.generic_string() + "\n";
    writeFileAtomically(root_ / kManifestName, list);
}

}  // namespace eikon::io
