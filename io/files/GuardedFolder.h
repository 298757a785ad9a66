// The writes of one process into an output folder: every temporary is
// created by eikon itself (O_EXCL, O_NOFOLLOW, relative to folders opened
// without following links) after it is recorded in the process's journal
// (RunJournal.h), and recorded again under its final name before renameat
// gives it that name. A writer that opens the temporary by name (VTK,
// OpenVDB) finds it there, a plain file eikon made. Every folder written
// into is recorded once, so that --force can remove it when it is left
// empty.
#pragma once

#include "io/files/AtomicFile.h"
#include "io/files/RunJournal.h"

#include <filesystem>
#include <mutex>
#include <set>

namespace eikon::io {

class GuardedFolder final : public WriteGuard {
public:
    // Guards the writes below `root`, open as `folder`, recording them in
    // `journal` (named `journalName` in messages), until destroyed. The
    // descriptors stay their owner's.
    GuardedFolder(std::filesystem::path root, int folder, int journal, std::filesystem::path journalName);
    ~GuardedFolder() override;
    GuardedFolder(const GuardedFolder&) = delete;
    GuardedFolder& operator=(const GuardedFolder&) = delete;

    Descriptor createTemporary(const std::filesystem::path& temporary) override;
    void commit(const std::filesystem::path& temporary, const std::filesystem::path& path) override;
    void discard(const std::filesystem::path& temporary) noexcept override;

    // Creates `relative` (plain names below the folder) exclusively, recorded
    // as `kind` (File, or Share for another process's journal) first.
    Descriptor createRecorded(const std::filesystem::path& relative, JournalEntry::Kind kind);

private:
    std::filesystem::path relativeOf(const std::filesystem::path& path) const;
    // The folder holding `relative`, opened without following links, and
    // recorded the first time it is written into.
    Descriptor openParent(const std::filesystem::path& relative);
    void record(const JournalEntry& entry);

    std::filesystem::path root_, journalName_;
    int folder_, journal_;
    std::mutex recordedFoldersMutex_;
    std::set<std::filesystem::path> recordedFolders_;
};

}  // namespace eikon::io
