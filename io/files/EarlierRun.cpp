#include "io/files/EarlierRun.h"

#include "io/files/RunJournal.h"

#include <algorithm>
#include <cerrno>
#include <optional>
#include <set>
#include <stdexcept>
#include <system_error>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace eikon::io {

namespace fs = std::filesystem;

namespace {

// The journal another process of the run kept, if it is still the file it
// created; empty otherwise.
std::string shareText(int folder, const fs::path& relative, const FileIdentity& identity) {
    try {
        const Descriptor parent = openFolderBeneath(folder, relative.parent_path());
        const Descriptor share(
            ::openat(parent.get(), relative.filename().c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC));
        struct stat status {};
        if (!share || ::fstat(share.get(), &status) != 0 || !S_ISREG(status.st_mode) || identityOf(status) != identity)
            return "";
        return readWholeFile(share.get());
    } catch (const std::system_error&) {
        return "";
    }
}

void collect(int folder, const std::vector<JournalEntry>& entries, bool withShares, std::vector<Removal>& removals,
             std::set<fs::path>& seen) {
    for (const JournalEntry& entry : entries) {
        const std::optional<struct stat> status = statBeneath(folder, entry.path);
        if (!status || seen.count(entry.path)) continue;
        const bool plainFile = S_ISREG(status->st_mode), created = identityOf(*status) == entry.identity;
        bool remove = false;
        switch (entry.kind) {
            case JournalEntry::Kind::Intent: remove = plainFile && status->st_size == 0; break;
            case JournalEntry::Kind::File: remove = plainFile && created; break;
            case JournalEntry::Kind::Folder: remove = S_ISDIR(status->st_mode) && created; break;
            case JournalEntry::Kind::Share:
                remove = withShares && plainFile && created;
                if (remove)
                    collect(folder, journalEntries(shareText(folder, entry.path, entry.identity)), false, removals, seen);
                break;
        }
        if (!remove) continue;
        seen.insert(entry.path);
        removals.push_back({entry.path, identityOf(*status), entry.kind == JournalEntry::Kind::Folder});
    }
}

}  // namespace

std::vector<Removal> earlierRunRemovals(int folder, const std::string& journal) {
    std::vector<Removal> removals;
    std::set<fs::path> seen;
    collect(folder, journalEntries(journal), true, removals, seen);
    return removals;
}

void removeEarlierRun(const fs::path& root, int folder, const std::vector<Removal>& removals) {
    std::vector<Removal> ordered = removals;
    const auto depth = [](const fs::path& path) { return std::distance(path.begin(), path.end()); };
    std::stable_sort(ordered.begin(), ordered.end(), [&](const Removal& a, const Removal& b) {
        if (a.folder != b.folder) return !a.folder;        // files first
        return a.folder && depth(a.path) > depth(b.path);  // then the deepest folders
    });
    for (const Removal& removal : ordered) {
        Descriptor parent;
        try {
            parent = openFolderBeneath(folder, removal.path.parent_path());
        } catch (const std::system_error&) {
            continue;  // its folder went, or became a link, since it was read
        }
        const fs::path name = removal.path.filename();
        struct stat status {};
        if (::fstatat(parent.get(), name.c_str(), &status, AT_SYMLINK_NOFOLLOW) != 0 || identityOf(status) != removal.identity)
            continue;
        if (::unlinkat(parent.get(), name.c_str(), removal.folder ? AT_REMOVEDIR : 0) == 0) continue;
        if (removal.folder && (errno == ENOTEMPTY || errno == EEXIST)) continue;  // it holds files eikon did not write
        throw std::runtime_error((root / removal.path).string() + ": cannot remove this file of an earlier run: " +
                                 std::generic_category().message(errno));
    }
}

}  // namespace eikon::io
