#include "io/files/OutputFolder.h"

#include "bridge/core/Error.h"
#include "io/files/AtomicFile.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <regex>
#include <system_error>
#include <vector>

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

// The files an earlier run's list names (only paths inside the folder).
std::vector<fs::path> listedFiles(const fs::path& root) {
    std::ifstream manifest(root / OutputFolder::kManifestName);
    std::vector<fs::path> files;
    std::string line;
    while (std::getline(manifest, line)) {
        if (line.empty() || line[0] == '#') continue;
        const fs::path relative = fs::path(line).lexically_normal();
        if (relative.is_absolute() || relative.empty() || *relative.begin() == "..") continue;
        files.push_back(relative);
    }
    return files;
}

// The names eikon gives its outputs (frames, report, VTK and OpenVDB
// series), relative to the folder.
const std::string kOutputNames =
    R"(report\.jsonl|frames/frame_\d{5}\.(png|hdr)|vdb/fields_\d{5}\.vdb|converge\.(csv|md|png|svg)|)"
    R"(vtk/((fields|receivers|meshes|photon_paths)(_\d{5}\.(vti|vtp)|\.pvd|\.(vti|vtp)\.series)|fields_static\.vti|)"
    R"(open_in_paraview\.py))";

// A temporary eikon was writing when it was killed (AtomicFile.h names
// them NAME.tmpPID): an output's, or the list's.
bool isEikonTemporary(const fs::path& relative) {
    static const std::regex temporary("(" + kOutputNames + R"(|\.eikon-run)\.tmp\d+)");
    return std::regex_match(relative.generic_string(), temporary);
}

// Runs from before the list existed: a folder all of whose files have the
// names eikon gives its outputs, or its temporaries'.
bool holdsOnlyUnlistedEikonOutput(const fs::path& root) {
    static const std::regex names(kOutputNames);
    const std::set<fs::path> files = filesBelow(root);
    return std::all_of(files.begin(), files.end(), [](const fs::path& file) {
        return std::regex_match(file.generic_string(), names) || isEikonTemporary(file);
    });
}

// Removes `files` and then the folders that left empty; the list goes last.
void clearEarlierRun(const fs::path& root, const std::vector<fs::path>& files) {
    std::set<fs::path> folders;
    for (const fs::path& relative : files) {
        std::error_code ignored;
        if (fs::is_regular_file(root / relative)) fs::remove(root / relative, ignored);
        for (fs::path parent = relative.parent_path(); !parent.empty(); parent = parent.parent_path()) folders.insert(parent);
    }
    for (auto folder = folders.rbegin(); folder != folders.rend(); ++folder) {  // deepest first
        std::error_code ignored;
        if (fs::is_directory(root / *folder) && fs::is_empty(root / *folder)) fs::remove(root / *folder, ignored);
    }
    std::error_code ignored;
    fs::remove(root / OutputFolder::kManifestName, ignored);
}

}  // namespace

void OutputFolder::requireUsable(const fs::path& root, bool force) {
    if (fs::exists(root) && !fs::is_directory(root)) throw InputError(root.string(), "an output folder", "a file");
    if (!fs::exists(root) || fs::is_empty(root)) return;
    if (!fs::is_regular_file(root / kManifestName) && !holdsOnlyUnlistedEikonOutput(root))
        throw InputError(root.string() +
                         ": the folder holds files eikon did not write; choose another --out (--force only clears "
                         "a folder an earlier eikon run wrote)");
    if (!force)
        throw InputError(root.string() +
                         ": the output folder holds an earlier run; choose another --out or pass --force to clear it");
}

OutputFolder::OutputFolder(fs::path root, bool force, bool withFrames) : root_(std::move(root)) {
    requireUsable(root_, force);
    if (fs::exists(root_) && !fs::is_empty(root_)) {
        const bool listed = fs::is_regular_file(root_ / kManifestName);
        const std::set<fs::path> all = filesBelow(root_);
        std::vector<fs::path> earlier = listed ? listedFiles(root_) : std::vector<fs::path>(all.begin(), all.end());
        for (const fs::path& file : all)  // what a killed run was writing
            if (listed && isEikonTemporary(file)) earlier.push_back(file);
        clearEarlierRun(root_, earlier);
    }
    fs::create_directories(withFrames ? root_ / "frames" : root_);
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

fs::path OutputFolder::framePathIn(const fs::path& root, int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05d.png", frame);
    return root / "frames" / name;
}

void OutputFolder::appendReport(const std::string& jsonLine) { appendReports({jsonLine}); }

void OutputFolder::appendReports(const std::vector<std::string>& jsonLines) {
    for (const std::string& line : jsonLines) report_ += line + "\n";
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
