// The memory a scene's run will take, estimated from its parsed sizes before
// anything is allocated, so that a scene too large for the machine is
// refused at once (exit code 2, naming the key that sized it, the bytes and
// the limit) rather than after gigabytes, or by the kernel's OOM killer on a
// smaller machine.
//
// Each documented size gives an item: its host arrays and the GL objects the
// renderer makes for it, as the stages that allocate them size them (named
// in MemoryEstimate.cpp). It counts what every scene of that kind allocates
// and leaves out what only some do (the fluence grids of a scattering
// medium, the fluid solver's fields, the process's own code and driver), so
// it is a floor: it refuses no scene that would fit. What it leaves out is
// still reserved against the same limit as each GL object is made
// (gl/GpuMemory.h). An imported volume's file and trees are checked as each
// grid is read (io/vdb/VdbVolumeFile.h), an environment map before it is
// decoded (io/scene).
#pragma once

#include "bridge/core/MemoryLimit.h"
#include "bridge/scene/Scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace eikon::render {

struct MemoryItem {
    std::string keyPath;  // the scene key that sizes it: "grid.resolution"
    std::string what;     // "the fields over 512×512×512 cells"
    std::uint64_t hostBytes = 0;
    std::uint64_t glBytes = 0;  // on the GPU, or in host memory for a renderer on the CPU
    std::uint64_t bytes() const { return hostBytes + glBytes; }
};

std::vector<MemoryItem> estimateMemory(const Scene& scene);

// InputError naming the scene file and the key of the largest item, with
// its bytes, the total and the limit, where the total passes the limit.
// Host and GL bytes count against one limit: they share memory where GL
// renders on the CPU, and a GPU's driver keeps host copies besides.
void requireMemoryFits(const Scene& scene, const MemoryLimit& limit = machineMemoryLimit());

}  // namespace eikon::render
