#include "io/files/NoFollow.h"

#include <cerrno>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

namespace eikon::io {

Descriptor& Descriptor::operator=(Descriptor&& other) noexcept {
    if (this != &other) {
        if (fd_ >= 0) ::close(fd_);
        fd_ = std::exchange(other.fd_, -1);
    }
    return *this;
}

Descriptor::~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
}

FileIdentity identityOf(const struct stat& status) { return {status.st_dev, status.st_ino}; }

bool isPlainRelative(const std::filesystem::path& relative) {
    if (relative.empty() || !relative.is_relative()) return false;
    for (const std::filesystem::path& part : relative)
        if (part.empty() || part == "." || part == "..") return false;
    return true;
}

Descriptor openFolderBeneath(int folder, const std::filesystem::path& relative) {
    Descriptor current(::fcntl(folder, F_DUPFD_CLOEXEC, 0));
    if (!current) throw std::system_error(errno, std::generic_category(), "cannot open its folder");
    if (relative.empty()) return current;
    if (!isPlainRelative(relative)) throw std::system_error(EINVAL, std::generic_category(), "not a path below the folder");
    for (const std::filesystem::path& part : relative) {
        Descriptor next(::openat(current.get(), part.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
        if (!next) {
            const int error = errno;
            // Linux says ENOTDIR, not ELOOP, for a link opened with
            // O_DIRECTORY | O_NOFOLLOW: the link is named as such.
            struct stat status {};
            if (::fstatat(current.get(), part.c_str(), &status, AT_SYMLINK_NOFOLLOW) == 0 && S_ISLNK(status.st_mode))
                throw std::system_error(ELOOP, std::generic_category(),
                                        part.string() + " is a symbolic link, which eikon does not follow");
            throw std::system_error(error, std::generic_category(), "cannot open " + part.string());
        }
        current = std::move(next);
    }
    return current;
}

std::optional<struct stat> statBeneath(int folder, const std::filesystem::path& relative) {
    if (!isPlainRelative(relative)) return std::nullopt;
    try {
        const Descriptor parent = openFolderBeneath(folder, relative.parent_path());
        struct stat status {};
        if (::fstatat(parent.get(), relative.filename().c_str(), &status, AT_SYMLINK_NOFOLLOW) != 0) return std::nullopt;
        return status;
    } catch (const std::system_error&) {
        return std::nullopt;
    }
}

}  // namespace eikon::io
