#include "io/files/OutputFolder.h"

#include "bridge/core/Error.h"
#include "io/files/AtomicFile.h"
#include "io/files/EarlierRun.h"
#include "io/files/RunJournal.h"

#include <cerrno>
#include <cstdio>
#include <optional>
#include <regex>
#include <set>
#include <stdexcept>
#include <system_error>

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace eikon::io {

namespace fs = std::filesystem;

namespace {

// The folders below DIR that eikon's writers open files in by name.
constexpr const char* kWrittenByName[] = {"frames", "vtk", "vdb"};

// The names eikon gives its outputs (frames, report, VTK and OpenVDB
// series, converge's study), relative to the folder.
const std::regex& outputNames() {
    static const std::regex names(
        R"(report\.jsonl|frames/frame_\d{5}\.(png|hdr)|vdb/fields_\d{5}\.vdb|converge\.(csv|md|png|svg)|)"
        R"(vtk/((fields|receivers|meshes|photon_paths)(_\d{5}\.(vti|vtp)|\.pvd|\.(vti|vtp)\.series)|fields_static\.vti|)"
        R"(open_in_paraview\.py))");
    return names;
}

std::string osReason() { return std::generic_category().message(errno); }

std::string shareJournalName(int rank) { return std::string(OutputFolder::kJournalName) + ".rank" + std::to_string(rank); }

Descriptor openRoot(const fs::path& root) {
    Descriptor folder(::open(root.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (!folder) throw std::runtime_error(root.string() + ": cannot open the output folder: " + osReason());
    return folder;
}

// The names in an open folder, in no particular order.
std::vector<std::string> namesIn(const fs::path& path, int folder) {
    DIR* listing = nullptr;
    if (const int own = ::openat(folder, ".", O_RDONLY | O_DIRECTORY | O_CLOEXEC); own >= 0) {
        listing = ::fdopendir(own);
        if (!listing) ::close(own);
    }
    if (!listing) throw std::runtime_error(path.string() + ": cannot read the output folder: " + osReason());
    std::vector<std::string> names;
    while (const dirent* entry = ::readdir(listing)) {
        const std::string name = entry->d_name;
        if (name != "." && name != "..") names.push_back(name);
    }
    ::closedir(listing);
    return names;
}

// "a, b (a symbolic link) and 3 more": the first few of `names` below `folder`.
std::string listed(int folder, const std::vector<fs::path>& names) {
    std::string text;
    constexpr std::size_t kShown = 3;
    for (std::size_t i = 0; i < names.size() && i < kShown; ++i) {
        const std::optional<struct stat> status = statBeneath(folder, names[i]);
        text += (i ? ", " : "") + names[i].generic_string() + (status && S_ISLNK(status->st_mode) ? " (a symbolic link)" : "");
    }
    if (names.size() > kShown) text += " and " + std::to_string(names.size() - kShown) + " more";
    return text;
}

[[noreturn]] void refuseForeign(const fs::path& root, int folder, const std::vector<std::string>& names) {
    throw InputError(root.string() + ": the folder holds files eikon did not write (" +
                     listed(folder, std::vector<fs::path>(names.begin(), names.end())) +
                     "); choose another --out (--force only clears a folder an earlier eikon run wrote)");
}

// The run's journal in `folder`, opened with `flags`; empty where there is none.
Descriptor openJournal(const fs::path& root, int folder, int flags) {
    Descriptor journal(::openat(folder, OutputFolder::kJournalName, flags | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0666));
    if (!journal && errno == ENOENT) return {};
    std::string found = journal ? "" : errno == ELOOP ? "a symbolic link" : "something it cannot open (" + osReason() + ")";
    struct stat status {};
    if (journal && (::fstat(journal.get(), &status) != 0 || !S_ISREG(status.st_mode))) found = "something else than a file";
    if (found.empty()) return journal;
    throw InputError((root / OutputFolder::kJournalName).string() + ": expected the journal of an eikon run, found " +
                     found + "; choose another --out");
}

[[noreturn]] void refuseBusy(const fs::path& root, int journal) {
    std::string holder = "another eikon run";
    try {
        if (const std::optional<long> pid = journalPid(readWholeFile(journal))) holder += " (pid " + std::to_string(*pid) + ")";
    } catch (const std::system_error&) {
        // Named without its pid.
    }
    throw std::runtime_error(holder + " is writing into " + root.string() +
                             "; wait for it to end or choose another --out");
}

struct flock wholeFileWriteLock() {
    struct flock lock {};
    lock.l_type = F_WRLCK;
    lock.l_whence = SEEK_SET;  // l_start 0, l_len 0: the whole file
    return lock;
}

void refuseIfBusy(const fs::path& root, int journal) {
    struct flock probe = wholeFileWriteLock();
    if (::fcntl(journal, F_OFD_GETLK, &probe) == 0 && probe.l_type != F_UNLCK) refuseBusy(root, journal);
}

void lockOrRefuse(const fs::path& root, int journal) {
    struct flock lock = wholeFileWriteLock();
    if (::fcntl(journal, F_OFD_SETLK, &lock) == 0) return;
    if (errno == EAGAIN || errno == EACCES) refuseBusy(root, journal);
    throw std::runtime_error((root / OutputFolder::kJournalName).string() + ": cannot lock: " + osReason());
}

// frames/, vtk/ and vdb/ are folders, not links: VTK and OpenVDB open the
// files in them by name.
void requireRealFolders(const fs::path& root, int folder) {
    for (const char* name : kWrittenByName) {
        struct stat status {};
        if (::fstatat(folder, name, &status, AT_SYMLINK_NOFOLLOW) != 0 || S_ISDIR(status.st_mode)) continue;
        throw InputError((root / name).string() + ": expected a folder for eikon's files, found " +
                         (S_ISLNK(status.st_mode) ? "a symbolic link" : "a file") +
                         "; eikon never writes through a link (remove it or choose another --out)");
    }
}

// Nothing under an output name stays once the earlier run's files go.
void requireNoStrangerOutputs(const fs::path& root, int folder, const std::vector<Removal>& removals) {
    std::set<fs::path> going;
    for (const Removal& removal : removals) going.insert(removal.path);
    std::vector<fs::path> strangers;
    const auto check = [&](const fs::path& subfolder, int descriptor) {
        for (const std::string& name : namesIn(root / subfolder, descriptor)) {
            const fs::path relative = subfolder / name;
            if (std::regex_match(relative.generic_string(), outputNames()) && !going.count(relative))
                strangers.push_back(relative);
        }
    };
    check({}, folder);
    for (const char* name : kWrittenByName) {
        const std::optional<struct stat> status = statBeneath(folder, name);
        if (status && S_ISDIR(status->st_mode)) check(name, openFolderBeneath(folder, name).get());
    }
    if (strangers.empty()) return;
    throw InputError(root.string() + ": " + listed(folder, strangers) +
                     ": not written by the earlier run (put there, or put in place of its file, since); eikon "
                     "neither overwrites such a file nor leaves it beside a new run's — move it away or choose "
                     "another --out");
}

// Every refusal; with `journal` (−1: none) holding an earlier run and
// `force`, what removing that run takes.
std::vector<Removal> checkFolder(const fs::path& root, int folder, int journal, bool force) {
    std::vector<std::string> names = namesIn(root, folder);
    std::erase(names, OutputFolder::kJournalName);
    std::string text;
    try {
        if (journal >= 0) text = readWholeFile(journal);
    } catch (const std::system_error& error) {
        throw std::runtime_error((root / OutputFolder::kJournalName).string() + ": " + error.what());
    }
    if (text.empty()) {  // no run, or one killed before its journal's first line
        if (!names.empty()) refuseForeign(root, folder, names);
        return {};
    }
    if (!journalPid(text))
        throw InputError((root / OutputFolder::kJournalName).string() +
                         ": expected the journal of an eikon run, which records each file's identity, found " +
                         (text.rfind("# files an eikon run wrote", 0) == 0 ? "an older eikon's list of names"
                                                                           : "another file") +
                         "; remove the earlier run's files yourself or choose another --out");
    if (!force)
        throw InputError(root.string() +
                         ": the output folder holds an earlier run; choose another --out or pass --force to clear it");
    const std::vector<Removal> removals = earlierRunRemovals(folder, text);
    requireRealFolders(root, folder);
    requireNoStrangerOutputs(root, folder, removals);
    return removals;
}

}  // namespace

void OutputFolder::requireUsable(const fs::path& root, bool force) {
    if (!fs::exists(root)) return;
    if (!fs::is_directory(root)) throw InputError(root.string(), "an output folder", "a file");
    const Descriptor folder = openRoot(root);
    const Descriptor journal = openJournal(root, folder.get(), O_RDONLY);
    if (journal) refuseIfBusy(root, journal.get());
    checkFolder(root, folder.get(), journal.get(), force);
}

OutputFolder::OutputFolder(fs::path root, bool force, bool withFrames) : root_(std::move(root)) {
    if (fs::exists(root_) && !fs::is_directory(root_)) throw InputError(root_.string(), "an output folder", "a file");
    std::error_code created;
    createdRoot_ = fs::create_directories(root_, created);
    if (created) throw std::runtime_error(root_.string() + ": cannot create the output folder: " + created.message());
    folder_ = openRoot(root_);
    journal_ = openJournal(root_, folder_.get(), O_RDWR | O_APPEND);
    if (!journal_) {  // made only in a folder that is empty: a refused one stays as it was
        if (std::vector<std::string> names = namesIn(root_, folder_.get()); !names.empty())
            refuseForeign(root_, folder_.get(), names);
        journal_ = openJournal(root_, folder_.get(), O_RDWR | O_APPEND | O_CREAT);
    }
    lockOrRefuse(root_, journal_.get());
    removeEarlierRun(root_, folder_.get(), checkFolder(root_, folder_.get(), journal_.get(), force));
    const std::string header = journalHeader(::getpid());
    if (::ftruncate(journal_.get(), 0) != 0 ||
        ::write(journal_.get(), header.data(), header.size()) != static_cast<ssize_t>(header.size()))
        throw std::runtime_error((root_ / kJournalName).string() + ": cannot be written: " + osReason());
    createdFrames_ = withFrames && ::mkdirat(folder_.get(), "frames", 0777) == 0;
    if (withFrames && !createdFrames_ && errno != EEXIST)
        throw std::runtime_error((root_ / "frames").string() + ": cannot be created: " + osReason());
    guard_ = std::make_unique<GuardedFolder>(root_, folder_.get(), journal_.get(), root_ / kJournalName);
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
}

void OutputFolder::recordScene(const std::string& fingerprint) {
    try {
        appendSceneToJournal(journal_.get(), fingerprint);
    } catch (const std::system_error& error) {
        throw std::runtime_error((root_ / kJournalName).string() + ": " + error.what());
    }
}

void OutputFolder::discard() {
    guard_.reset();  // no more writes are recorded
    std::string text;
    try {
        text = readWholeFile(journal_.get());
    } catch (const std::system_error& error) {
        throw std::runtime_error((root_ / kJournalName).string() + ": " + error.what());
    }
    removeEarlierRun(root_, folder_.get(), earlierRunRemovals(folder_.get(), text));
    if (createdFrames_) ::unlinkat(folder_.get(), "frames", AT_REMOVEDIR);  // only while empty
    // The journal goes only while it is still the file this run holds.
    struct stat held {}, named {};
    if (::fstat(journal_.get(), &held) == 0 &&
        ::fstatat(folder_.get(), kJournalName, &named, AT_SYMLINK_NOFOLLOW) == 0 && held.st_dev == named.st_dev &&
        held.st_ino == named.st_ino)
        ::unlinkat(folder_.get(), kJournalName, 0);
    journal_ = Descriptor();
    folder_ = Descriptor();
    if (createdRoot_) ::rmdir(root_.c_str());  // only while empty: anything another program saved there stays
}

void OutputFolder::shareWith(int processes) {
    for (int rank = 1; rank < processes; ++rank) {
        try {
            guard_->createRecorded(shareJournalName(rank), JournalEntry::Kind::Share);
        } catch (const std::system_error& error) {
            throw std::runtime_error((root_ / shareJournalName(rank)).string() + ": " + error.what());
        }
    }
}

OutputFolderShare::OutputFolderShare(const fs::path& root, int rank) : folder_(openRoot(root)) {
    const std::string name = shareJournalName(rank);
    journal_ = Descriptor(::openat(folder_.get(), name.c_str(), O_WRONLY | O_APPEND | O_NOFOLLOW | O_CLOEXEC));
    if (!journal_) throw std::runtime_error((root / name).string() + ": cannot open this process's journal: " + osReason());
    guard_ = std::make_unique<GuardedFolder>(root, folder_.get(), journal_.get(), root / name);
}

}  // namespace eikon::io
