#include "io/files/GuardedFolder.h"

#include <cerrno>
#include <string>
#include <system_error>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace eikon::io {

namespace fs = std::filesystem;

namespace {

std::system_error osError(const std::string& step) { return {errno, std::generic_category(), step}; }

}  // namespace

GuardedFolder::GuardedFolder(fs::path root, int folder, int journal, fs::path journalName)
    : root_(std::move(root)), journalName_(std::move(journalName)), folder_(folder), journal_(journal) {
    guardWritesBelow(root_, *this);
}

GuardedFolder::~GuardedFolder() { stopGuarding(*this); }

fs::path GuardedFolder::relativeOf(const fs::path& path) const {
    const fs::path relative = path.lexically_normal().lexically_relative(root_.lexically_normal());
    if (!isPlainRelative(relative))
        throw std::system_error(EINVAL, std::generic_category(), "not below the output folder " + root_.string());
    return relative;
}

void GuardedFolder::record(const JournalEntry& entry) {
    try {
        appendToJournal(journal_, entry);
    } catch (const std::system_error& error) {
        throw std::system_error(error.code(), "cannot record it in " + journalName_.string());
    }
}

Descriptor GuardedFolder::openParent(const fs::path& relative) {
    const fs::path parent = relative.parent_path();
    Descriptor folder = openFolderBeneath(folder_, parent);
    const std::lock_guard lock(recordedFoldersMutex_);
    fs::path prefix;
    for (const fs::path& part : parent) {
        prefix /= part;
        if (!recordedFolders_.insert(prefix).second) continue;
        const std::optional<struct stat> status = statBeneath(folder_, prefix);
        if (status && S_ISDIR(status->st_mode)) record({JournalEntry::Kind::Folder, identityOf(*status), prefix});
    }
    return folder;
}

Descriptor GuardedFolder::createRecorded(const fs::path& relative, JournalEntry::Kind kind) {
    const Descriptor parent = openParent(relative);
    record({JournalEntry::Kind::Intent, {}, relative});
    Descriptor file(::openat(parent.get(), relative.filename().c_str(),
                             O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666));
    struct stat status {};
    if (!file || ::fstat(file.get(), &status) != 0) throw osError("cannot write");
    try {
        record({kind, identityOf(status), relative});
    } catch (const std::system_error&) {
        ::unlinkat(parent.get(), relative.filename().c_str(), 0);
        throw;
    }
    return file;
}

Descriptor GuardedFolder::createTemporary(const fs::path& temporary) {
    return createRecorded(relativeOf(temporary), JournalEntry::Kind::File);
}

void GuardedFolder::commit(const fs::path& temporary, const fs::path& path) {
    const fs::path from = relativeOf(temporary), to = relativeOf(path);
    const Descriptor fromFolder = openParent(from), toFolder = openParent(to);
    // O_NONBLOCK: something put in its place that is not a plain file (a
    // FIFO) must not stall the run; it is refused below.
    const Descriptor file(::openat(fromFolder.get(), from.filename().c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC));
    struct stat status {};
    if (!file || ::fstat(file.get(), &status) != 0) throw osError("could not be written");
    if (!S_ISREG(status.st_mode)) throw std::system_error(EINVAL, std::generic_category(), "its temporary is not a plain file");
    if (::fsync(file.get()) != 0) throw osError("could not be written");
    record({JournalEntry::Kind::File, identityOf(status), to});
    if (::renameat(fromFolder.get(), from.filename().c_str(), toFolder.get(), to.filename().c_str()) != 0)
        throw osError("cannot rename into place");
}

void GuardedFolder::discard(const fs::path& temporary) noexcept {
    try {
        const fs::path relative = relativeOf(temporary);
        const Descriptor parent = openFolderBeneath(folder_, relative.parent_path());
        ::unlinkat(parent.get(), relative.filename().c_str(), 0);
    } catch (const std::exception&) {
        // Nothing to remove where the temporary cannot be reached.
    }
}

}  // namespace eikon::io
