#include "bridge/core/MemoryLimit.h"

#include <sys/sysinfo.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace eikon {

namespace {

constexpr const char* kVariable = "EIKON_MEMORY_LIMIT_MB";
constexpr std::uint64_t kMebibyte = 1024 * 1024;

}  // namespace

std::optional<MemoryLimit> memoryLimitFromEnvironment() {
    const char* text = std::getenv(kVariable);
    if (!text) return std::nullopt;
    char* end = nullptr;
    errno = 0;
    const unsigned long long value = std::strtoull(text, &end, 10);
    if (end == text || *end != '\0' || errno == ERANGE || value < 1 || value > UINT64_MAX / kMebibyte ||
        text[0] == '-' || text[0] == '+')
        throw std::runtime_error(std::string(kVariable) + ": expected a whole number of MiB of at least 1, found \"" +
                                 text + "\"");
    return MemoryLimit{value * kMebibyte, mebibytes(value * kMebibyte) + " (" + kVariable + ")"};
}

MemoryLimit machineMemoryLimit() {
    if (std::optional<MemoryLimit> lowered = memoryLimitFromEnvironment()) return *lowered;
    struct sysinfo machine {};
    if (sysinfo(&machine) != 0) return {};
    const std::uint64_t bytes = (std::uint64_t(machine.totalram) + machine.totalswap) * machine.mem_unit;
    return {bytes, "the machine's " + mebibytes(bytes) + " of memory and swap"};
}

std::string mebibytes(std::uint64_t bytes) {
    const double value = static_cast<double>(bytes) / static_cast<double>(kMebibyte);
    char text[48];
    std::snprintf(text, sizeof text, value >= 100.0 ? "%.0f MiB" : "%.3g MiB", value);
    return text;
}

}  // namespace eikon
