// Paths below an open folder, reached without following a symbolic link:
// each folder on the way is opened relative to the one before it with
// O_NOFOLLOW, so a link anywhere below the folder (frames/ pointing at a
// user's pictures, a journal line "link/notes.txt") ends the walk instead of
// leading outside. (Linux's openat2 with RESOLVE_NO_SYMLINKS does the same
// in one call, from Linux 5.6 and without a glibc wrapper; these are POSIX.)
#pragma once

#include <filesystem>
#include <optional>
#include <utility>

#include <sys/stat.h>
#include <sys/types.h>

namespace eikon::io {

// An open file descriptor, closed with its owner.
class Descriptor {
public:
    Descriptor() = default;
    explicit Descriptor(int fd) : fd_(fd) {}
    Descriptor(Descriptor&& other) noexcept : fd_(std::exchange(other.fd_, -1)) {}
    Descriptor& operator=(Descriptor&& other) noexcept;
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    ~Descriptor();

    int get() const { return fd_; }
    explicit operator bool() const { return fd_ >= 0; }
    // Hands the descriptor over (to close it and see what close says).
    int release() { return std::exchange(fd_, -1); }

private:
    int fd_ = -1;
};

// What tells a file from another that later takes its name.
struct FileIdentity {
    dev_t device = 0;
    ino_t inode = 0;
    bool operator==(const FileIdentity&) const = default;
};
FileIdentity identityOf(const struct stat& status);

// True where `relative` is made of plain names only: not empty, not
// absolute, no "." or "..".
bool isPlainRelative(const std::filesystem::path& relative);

// The folder `relative` (plain names; empty: `folder` itself) below the open
// folder `folder`. Throws std::system_error with the OS's code; ELOOP, with
// a message naming it, where a part of the way is a symbolic link.
Descriptor openFolderBeneath(int folder, const std::filesystem::path& relative);

// lstat of `relative` (plain names) below `folder`: nullopt where it, or a
// folder on the way, is missing or where the way goes through a link.
std::optional<struct stat> statBeneath(int folder, const std::filesystem::path& relative);

}  // namespace eikon::io
