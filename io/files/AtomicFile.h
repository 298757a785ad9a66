// Whole-file writes that never leave a truncated file behind: the bytes go to
// a temporary name beside the target, are flushed, and are renamed over it.
// Below a folder a WriteGuard guards (an output folder), the guard creates
// the temporary and renames it, recording both first; elsewhere the file
// system is used by path.
#pragma once

#include "io/files/NoFollow.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace eikon::io {

// Throws std::runtime_error naming the path and the OS's reason on any
// failure; the target is then untouched and the temporary removed.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

// For writers that stream a file themselves (VTK, OpenVDB): the temporary
// name beside `path` to write to (in a guarded folder already created,
// empty, for the writer to open by that name), and the step that flushes it
// to disk and renames it over `path` once `written` (removing it otherwise
// or on failure; std::runtime_error naming `path` then).
std::filesystem::path temporaryPathFor(const std::filesystem::path& path);
// `reason`: why the writer failed, when it says (for the message).
void commitTemporary(const std::filesystem::path& temporary, const std::filesystem::path& path, bool written,
                     const std::string& reason = "");

// A folder whose writes eikon guards (OutputFolder): it creates each
// temporary below it and renames it into place itself, recording both, and
// never follows a link on the way. Errors: std::system_error whose text says
// the step that failed ("cannot rename into place").
class WriteGuard {
public:
    virtual ~WriteGuard() = default;
    // Creates `temporary` (empty, exclusively) and returns it open for writing.
    virtual Descriptor createTemporary(const std::filesystem::path& temporary) = 0;
    // Flushes the written `temporary` to disk and renames it over `path`.
    virtual void commit(const std::filesystem::path& temporary, const std::filesystem::path& path) = 0;
    // Removes a temporary that was not written whole.
    virtual void discard(const std::filesystem::path& temporary) noexcept = 0;
};
// From now on the writes below `root` (as the writers spell it: the paths
// they are given start with it) go through `guard`, until stopGuarding;
// where two guard one folder, the later one.
void guardWritesBelow(const std::filesystem::path& root, WriteGuard& guard);
void stopGuarding(const WriteGuard& guard);

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
