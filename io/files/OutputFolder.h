// The output folder of a run: DIR/frames/frame_NNNNN.png, DIR/report.jsonl
// and whatever the exporters add — a resource eikon guards:
//
// - Nothing eikon did not write is removed. DIR/.eikon-run, the run's
//   journal (RunJournal.h), lists every file and folder eikon creates there
//   by identity (device and inode), recorded as eikon creates it and before
//   it takes its final name — never by scanning the folder, so a file
//   another program saves there during the run is not the run's. `--force`
//   on a folder holding an earlier run removes what that journal lists and
//   is still the file it created (EarlierRun.h), the files of a run killed
//   with -9 included, and nothing else. A folder without a journal holds no
//   earlier run: if it is not empty it is refused, --force or not.
// - No symbolic link below DIR is followed. Of the two ways there — refuse
//   a folder that holds links, or reach every file through descriptors
//   opened with O_NOFOLLOW — eikon takes the second wherever it creates,
//   renames or removes a file itself (GuardedFolder.h, EarlierRun.h): a
//   user's link elsewhere in the folder, or a journal line through one,
//   then reaches nothing and the link is left alone, where refusing would
//   turn away a folder that is safe to use. Where a library opens a file by
//   name (VTK and OpenVDB write into vtk/ and vdb/), a link cannot be told
//   apart on the way, so frames/, vtk/ and vdb/ must be real folders: one
//   that is a link is refused, named (exit 2). DIR itself is used as named,
//   link or not: the user chose it.
// - One run at a time: a run holds a lock on its journal; a second run into
//   the folder stops at once, before it writes anything, with exit 1 (a
//   resource in use, as a busy device is: the same command succeeds once
//   the first run ends) and "another eikon run (pid N) is writing into
//   DIR". The lock is an open file description lock (F_OFD_SETLK), which a
//   run can test for without taking it (F_OFD_GETLK): with flock, a run
//   that only looks could make the one that takes it fail.
// - Two runs' files never sit side by side: a file under one of eikon's
//   output names that the earlier run did not write (put there, or put in
//   place of one of its files, since) is refused, named, rather than
//   overwritten or left beside the new run's.
#pragma once

#include "io/files/GuardedFolder.h"
#include "io/files/NoFollow.h"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace eikon::io {

class OutputFolder {
public:
    // Throws InputError (exit code 2) for a folder it refuses (above), and
    // std::runtime_error (exit code 1) where another run is writing into it
    // or it cannot be created, read or locked. withFrames: with its frames/
    // folder (`eikon converge` writes no frames).
    OutputFolder(std::filesystem::path root, bool force, bool withFrames = true);
    // The same refusals, without touching the folder: for a run that
    // checks everything before it writes anything.
    static void requireUsable(const std::filesystem::path& root, bool force);

    const std::filesystem::path& root() const { return root_; }
    std::filesystem::path framePath(int frame) const { return framePathIn(root_, frame); }
    // DIR/frames/frame_NNNNN.png of the folder `root` (for the processes of a
    // run that write frames into a folder another one opened).
    static std::filesystem::path framePathIn(const std::filesystem::path& root, int frame);

    // Appends one JSON line to report.jsonl, rewriting the file atomically so
    // a reader never sees half a line.
    void appendReport(const std::string& jsonLine);
    // The same for several lines at once, in order (one rewrite).
    void appendReports(const std::vector<std::string>& jsonLines);

    // Records the fingerprint of the scene the run renders in the journal
    // (RunJournal.h's scene line). std::runtime_error when it cannot.
    void recordScene(const std::string& fingerprint);

    // Removes everything this run wrote (what its journal lists, as --force
    // would), its journal, and the folder itself where the run created it
    // and it is left empty: for a run stopped by an input it found bad only
    // after its first frame was written. Nothing else is touched.
    void discard();

    // Makes the journals of the other processes of a run that write into
    // this folder (MPI ranks 1 … processes − 1), before they start:
    // OutputFolderShare opens each.
    void shareWith(int processes);

    static constexpr const char* kJournalName = ".eikon-run";

private:
    std::filesystem::path root_;
    bool createdRoot_ = false;     // the folder did not exist before this run
    bool createdFrames_ = false;   // nor its frames/
    Descriptor folder_, journal_;  // the journal holds the lock
    std::unique_ptr<GuardedFolder> guard_;
    std::string report_;
};

// The share of a run's output folder that another process of the run (MPI
// rank `rank` > 0) writes its files into, recorded in the journal rank 0
// made for it (OutputFolder::shareWith), so that --force clears them too.
class OutputFolderShare {
public:
    OutputFolderShare(const std::filesystem::path& root, int rank);

private:
    Descriptor folder_, journal_;
    std::unique_ptr<GuardedFolder> guard_;
};

}  // namespace eikon::io
