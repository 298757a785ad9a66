// Whole-file writes that never leave a truncated file behind: the bytes go to
// a temporary name beside the target, are flushed, and are renamed over it.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace eikon::io {

// Throws std::runtime_error naming the path on any failure; the target is
// then untouched and the temporary removed.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

// For writers that stream a file themselves (VTK, OpenVDB): the temporary
// name beside `path` to write to, and the step that flushes it to disk and
// renames it over `path` once `written` (removing it otherwise or on
// failure; std::runtime_error naming `path` then).
std::filesystem::path temporaryPathFor(const std::filesystem::path& path);
// `reason`: why the writer failed, when it says (for the message).
void commitTemporary(const std::filesystem::path& temporary, const std::filesystem::path& path, bool written,
                     const std::string& reason = "");

// Makes SIGINT, SIGTERM and SIGHUP remove the temporaries being written
// (temporaryPathFor to commitTemporary, and writeFileAtomically's own)
// before the process ends by the signal as it would have: an interrupted
// run leaves only whole files under their final names and no temporaries.
// (kill -9 cannot be caught: OutputFolder clears what it leaves.)
void removeTemporariesOnSignals();
// From now on such a signal, once the temporaries are removed, writes
// `message` to stderr and ends the process with exit code `code` instead:
// for a rank of an MPI job, whose launcher passes an exit code on but
// reports a death by signal as a crash of its own.
void exitOnSignalsWith(int code, const std::string& message);

}  // namespace eikon::io
