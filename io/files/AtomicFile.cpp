#include "io/files/AtomicFile.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <mutex>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

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

std::filesystem::path temporaryNameFor(const std::filesystem::path& path) {
    return path.string() + ".tmp" + std::to_string(::getpid());
}

// The folders whose writes are guarded, by root as the writers spell it.
std::mutex guardsMutex;
std::vector<std::pair<std::filesystem::path, WriteGuard*>> guards;

bool isBelow(const std::filesystem::path& root, const std::filesystem::path& path) {
    const std::filesystem::path relative = path.lexically_normal().lexically_relative(root.lexically_normal());
    return isPlainRelative(relative);
}

WriteGuard* guardFor(const std::filesystem::path& path) {
    const std::lock_guard lock(guardsMutex);
    for (auto entry = guards.rbegin(); entry != guards.rend(); ++entry)  // the latest first
        if (isBelow(entry->first, path)) return entry->second;
    return nullptr;
}

std::system_error osError(const std::string& step) { return {errno, std::generic_category(), step}; }

// The same steps by path, where no folder guards them.
class PathWrites final : public WriteGuard {
public:
    Descriptor createTemporary(const std::filesystem::path& temporary) override {
        Descriptor file(::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0666));
        if (!file) throw osError("cannot write");
        return file;
    }
    void commit(const std::filesystem::path& temporary, const std::filesystem::path& path) override {
        const Descriptor file(::open(temporary.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC));
        if (!file || ::fsync(file.get()) != 0) throw osError("could not be written");
        if (::rename(temporary.c_str(), path.c_str()) != 0) throw osError("cannot rename into place");
    }
    void discard(const std::filesystem::path& temporary) noexcept override { ::unlink(temporary.c_str()); }
};

WriteGuard& writesFor(const std::filesystem::path& path) {
    static PathWrites byPath;
    WriteGuard* guard = guardFor(path);
    return guard ? *guard : byPath;
}

// All of `bytes` to `file`, or the OS's reason why not.
void writeAll(int file, std::string_view bytes) {
    while (!bytes.empty()) {
        const ssize_t written = ::write(file, bytes.data(), bytes.size());
        if (written < 0 && errno == EINTR) continue;
        if (written < 0) throw osError("write failed");
        bytes.remove_prefix(static_cast<std::size_t>(written));
    }
}

// Renames a written temporary into place, or removes it and says why not.
void commitOrDiscard(WriteGuard& writes, const std::filesystem::path& temporary, const std::filesystem::path& path) {
    try {
        writes.commit(temporary, path);
    } catch (const std::system_error& error) {
        writes.discard(temporary);
        throw std::runtime_error(path.string() + ": " + error.what());
    }
}

}  // namespace

std::filesystem::path temporaryPathFor(const std::filesystem::path& path) {
    const std::filesystem::path temporary = temporaryNameFor(path);
    registerTemporary(temporary);
    if (WriteGuard* guard = guardFor(path)) {
        try {
            guard->createTemporary(temporary);  // closed again: the writer opens it by name
        } catch (const std::system_error& error) {
            unregisterTemporary(temporary);
            throw std::runtime_error(path.string() + ": " + error.what());
        }
    }
    return temporary;
}

void guardWritesBelow(const std::filesystem::path& root, WriteGuard& guard) {
    const std::lock_guard lock(guardsMutex);
    guards.emplace_back(root, &guard);
}

void stopGuarding(const WriteGuard& guard) {
    const std::lock_guard lock(guardsMutex);
    std::erase_if(guards, [&](const auto& entry) { return entry.second == &guard; });
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
    WriteGuard& writes = writesFor(path);
    if (!written) {
        writes.discard(temporary);
        throw std::runtime_error(path.string() + ": could not be written" + (reason.empty() ? "" : " (" + reason + ")"));
    }
    commitOrDiscard(writes, temporary, path);
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes) {
    const std::filesystem::path temporary = temporaryNameFor(path);
    registerTemporary(temporary);
    const InFlight inFlight{temporary};
    WriteGuard& writes = writesFor(path);
    try {
        Descriptor file = writes.createTemporary(temporary);
        try {
            writeAll(file.get(), bytes);
        } catch (const std::system_error&) {
            writes.discard(temporary);
            throw;
        }
        if (::close(file.release()) != 0) {  // NFS, say, reports a failed write only here
            const std::system_error error = osError("write failed");
            writes.discard(temporary);
            throw error;
        }
    } catch (const std::system_error& error) {
        throw std::runtime_error(path.string() + ": " + error.what());
    }
    commitOrDiscard(writes, temporary, path);
}

}  // namespace eikon::io
