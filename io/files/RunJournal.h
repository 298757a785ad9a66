// DIR/.eikon-run, the journal of the run that writes into an output folder:
// every file and folder eikon creates there, by name and identity (device
// and inode), recorded when eikon creates it — never found by scanning the
// folder. A file's temporary is recorded before it is created and once
// created, and the file again under its final name before the rename, each
// line one write(2) on a descriptor opened with O_APPEND: a process killed
// at any moment has recorded everything it leaves. (The lines reach the
// disk with the page cache: a kill loses none; a power cut may lose the
// last ones.)
//
//   # eikon run journal, format 2, pid 4242: ...       the header
//   new     frames/frame_00003.png.tmp4242              about to be created
//   file    2049  1834  frames/frame_00003.png.tmp4242  created: its identity
//   file    2049  1834  frames/frame_00003.png          about to take this name
//   folder  2049  1790  frames                          a folder written into
//   share   2049  1801  .eikon-run.rank1                another process's journal
//   scene   9e107d9d372bb6826bd81d3542a419d6            the scene it rendered
//
// Fields are separated by tabs; paths are relative to the folder. A share
// is the journal of another process of the run (an MPI rank) writing into
// the same folder: entries only, no header. The scene line holds the
// fingerprint of the scene the run rendered (io/scene/SceneFingerprint.h),
// which `eikon paraview` checks its scene against.
#pragma once

#include "io/files/NoFollow.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <sys/types.h>

namespace eikon::io {

struct JournalEntry {
    enum class Kind { Intent, File, Folder, Share };
    Kind kind = Kind::Intent;
    FileIdentity identity;  // all but Intent
    std::filesystem::path path;
};

// The first line of a run's journal, naming the process that holds it.
std::string journalHeader(pid_t pid);
// The pid the header of `text` names; nullopt where `text` is not a journal
// of this format (an older eikon's list of names, another program's file).
std::optional<long> journalPid(const std::string& text);
// Every entry of `text` whose path is plain names below the folder; other
// lines (the header, one cut short) are skipped.
std::vector<JournalEntry> journalEntries(const std::string& text);

// One line, in one write(2). Throws std::system_error.
void appendToJournal(int journal, const JournalEntry& entry);
// The scene line, in one write(2). Throws std::system_error.
void appendSceneToJournal(int journal, const std::string& fingerprint);
// The fingerprint the scene line of `text` holds; nullopt where it has none
// (a run of an older eikon, or one killed before it recorded it).
std::optional<std::string> journalScene(const std::string& text);
// The whole of an open file. Throws std::system_error.
std::string readWholeFile(int fd);

}  // namespace eikon::io
