// The memory eikon may take on this machine, host and GL together where GL
// renders on the CPU: the machine's memory and swap (beyond them Linux can
// only overcommit, and a process that touches what it was promised is
// killed), or less where the environment variable EIKON_MEMORY_LIMIT_MB
// says so (a smaller share of a busy machine; tests show refusals under a
// lowered limit without allocating). gl/GpuMemory.h reserves GL objects
// against it; render/graph/MemoryEstimate.h checks a scene's sizes against
// it before anything is allocated.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace eikon {

struct MemoryLimit {
    std::uint64_t bytes = 0;  // 0: unknown (no limit is applied)
    std::string source;       // how it was found, for messages
};

// EIKON_MEMORY_LIMIT_MB where it is set; std::runtime_error naming the
// variable where it is not a whole number of MiB of at least 1.
std::optional<MemoryLimit> memoryLimitFromEnvironment();

// The lowered limit where there is one, else the machine's memory and swap.
MemoryLimit machineMemoryLimit();

// "4096 MiB": the unit every memory message uses.
std::string mebibytes(std::uint64_t bytes);

}  // namespace eikon
