#include "io/files/AtomicFile.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <fcntl.h>
#include <unistd.h>

namespace eikon::io {

namespace {

// Flushes a file another library has written and closed to the disk.
bool syncFile(const std::filesystem::path& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const bool synced = ::fsync(fd) == 0;
    return ::close(fd) == 0 && synced;
}

}  // namespace

std::filesystem::path temporaryPathFor(const std::filesystem::path& path) {
    return path.string() + ".tmp" + std::to_string(::getpid());
}

void commitTemporary(const std::filesystem::path& temporary, const std::filesystem::path& path, bool written) {
    written = written && syncFile(temporary);
    std::error_code error;
    if (written) std::filesystem::rename(temporary, path, error);
    if (!written || error) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw std::runtime_error(path.string() + (written ? ": cannot rename into place (" + error.message() + ")"
                                                         : ": could not be written"));
    }
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
    const std::filesystem::path temporary = temporaryPathFor(path);
    std::FILE* file = std::fopen(temporary.c_str(), "wb");
    if (!file) throw std::runtime_error(path.string() + ": cannot write (" + std::strerror(errno) + ")");
    const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size() && std::fflush(file) == 0 &&
                         ::fsync(::fileno(file)) == 0;
    const int writeErrno = errno;
    const bool closed = std::fclose(file) == 0;
    std::error_code error;
    if (!written || !closed) {
        std::filesystem::remove(temporary, error);
        throw std::runtime_error(path.string() + ": write failed (" + std::strerror(writeErrno) + ")");
    }
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::filesystem::remove(temporary, error);
        throw std::runtime_error(path.string() + ": cannot rename into place (" + error.message() + ")");
    }
}

}  // namespace eikon::io
