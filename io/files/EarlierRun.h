// What `--force` removes of an earlier run in an output folder: each file and
// folder its journal lists (RunJournal.h) — and the journals of the processes
// that shared the folder with it, with theirs — that is still the one it
// created: the same kind, device and inode, reached from the folder without
// following a link. A temporary recorded only as about to be created (the
// run was killed between creating it and recording its identity) goes only
// while it is an empty plain file. Anything else stays, whatever the
// journal says: a file another program saved there, or put in the place of
// one of the run's, and whatever a line reaches through a link.
#pragma once

#include "io/files/NoFollow.h"

#include <filesystem>
#include <string>
#include <vector>

namespace eikon::io {

struct Removal {
    std::filesystem::path path;  // relative to the folder
    FileIdentity identity;
    bool folder = false;
};

// Reads the files and folders to remove; touches nothing.
std::vector<Removal> earlierRunRemovals(int folder, const std::string& journal);

// Removes them: the files, then the folders they leave empty (deepest
// first), each checked once more just before. Throws std::runtime_error
// naming a file below `root` that cannot be removed.
void removeEarlierRun(const std::filesystem::path& root, int folder, const std::vector<Removal>& removals);

}  // namespace eikon::io
