#include "io/files/AtomicFile.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <fcntl.h>
#include <unistd.h>

namespace eikon::io {

namespace {

// The temporaries being written, for the signal handler: fixed slots of
// plain characters, each published by an atomic flag once its name is
// complete, since a handler may only read lock-free atomics and call
// async-signal-safe functions (unlink).
constexpr std::size_t kSlots = 64, kLongestPath = 4096;
std::array<std::array<char, kLongestPath>, kSlots> inFlightPaths;
std::array<std::atomic<bool>, kSlots> inFlightUsed{};
std::atomic<bool> slotTaken[kSlots] = {};

void registerTemporary(const std::filesystem::path& temporary) {
    const std::string name = temporary.string();
    if (name.size() >= kLongestPath) return;  // not removable on a signal; still removed on failure
    for (std::size_t slot = 0; slot < kSlots; ++slot) {
        bool expected = false;
        if (!slotTaken[slot].compare_exchange_strong(expected, true)) continue;
        std::copy(name.begin(), name.end(), inFlightPaths[slot].begin());
        inFlightPaths[slot][name.size()] = '\0';
        inFlightUsed[slot].store(true, std::memory_order_release);
        return;
    }
}

void unregisterTemporary(const std::filesystem::path& temporary) {
    const std::string name = temporary.string();
    for (std::size_t slot = 0; slot < kSlots; ++slot) {
        if (!inFlightUsed[slot].load(std::memory_order_acquire) || name != inFlightPaths[slot].data()) continue;
        inFlightUsed[slot].store(false, std::memory_order_release);
        slotTaken[slot].store(false);
        return;
    }
}

// Unregisters a temporary when its writer is done with it, however it ends.
struct InFlight {
    const std::filesystem::path& temporary;
    ~InFlight() { unregisterTemporary(temporary); }
};

// What a signal ends the process with after the temporaries (exitOnSignalsWith):
// set before the handlers may run, then only read.
std::atomic<int> signalExitCode{-1};
std::array<char, 512> signalMessage{};
std::atomic<std::size_t> signalMessageLength{0};

extern "C" void removeTemporariesAndDie(int signal) {
    for (std::size_t slot = 0; slot < kSlots; ++slot)
        if (inFlightUsed[slot].load(std::memory_order_acquire)) ::unlink(inFlightPaths[slot].data());
    if (const int code = signalExitCode.load(); code >= 0) {
        const ssize_t ignored = ::write(STDERR_FILENO, signalMessage.data(), signalMessageLength.load());
        (void)ignored;
        ::_exit(code);
    }
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

// Flushes a file another library has written and closed to the disk.
bool syncFile(const std::filesystem::path& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const bool synced = ::fsync(fd) == 0;
    return ::close(fd) == 0 && synced;
}

}  // namespace

std::filesystem::path temporaryPathFor(const std::filesystem::path& path) {
    const std::filesystem::path temporary = path.string() + ".tmp" + std::to_string(::getpid());
    registerTemporary(temporary);
    return temporary;
}

void removeTemporariesOnSignals() {
    for (const int signal : {SIGINT, SIGTERM, SIGHUP}) std::signal(signal, removeTemporariesAndDie);
}

void exitOnSignalsWith(int code, const std::string& message) {
    const std::size_t length = std::min(message.size(), signalMessage.size());
    std::copy_n(message.begin(), length, signalMessage.begin());
    signalMessageLength.store(length);
    signalExitCode.store(code);
}

void commitTemporary(const std::filesystem::path& temporary, const std::filesystem::path& path, bool written,
                     const std::string& reason) {
    const InFlight inFlight{temporary};
    written = written && syncFile(temporary);
    std::error_code error;
    if (written) std::filesystem::rename(temporary, path, error);
    if (!written || error) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw std::runtime_error(path.string() + (written ? ": cannot rename into place (" + error.message() + ")"
                                                         : ": could not be written" +
                                                               (reason.empty() ? "" : " (" + reason + ")")));
    }
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
    const std::filesystem::path temporary = temporaryPathFor(path);
    const InFlight inFlight{temporary};
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
