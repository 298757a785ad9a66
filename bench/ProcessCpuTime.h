// CPU time of the whole process (all threads), for benchmarks on a shared
// machine: the wall time depends on the other load, the work done does not.
#pragma once

#include <sys/resource.h>

namespace eikon::bench {

inline double processCpuMs() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return 1e3 * (usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) + 1e-3 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

}  // namespace eikon::bench
