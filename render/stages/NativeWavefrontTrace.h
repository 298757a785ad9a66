// The wavefront pass on the CPU: the very text of the compute shader's
// patches and rays (shaders/common/wavefront_patches.glsl and what it
// includes), compiled as C++ through cpp_shim.h and run as TBB loops over a
// level's rays and patches, the levels driven here with no round trip. Each
// thread sums its deposits into its own 64-bit integers in the shader's
// fixed-point units, as the native photon pass does (NativePhotonTrace.h):
// integer sums do not depend on their order, so a pass gives the same bits
// run to run, and the same integers as the compute shader's atomics wherever
// its rays took the same paths. A level's children are placed in the order
// of their parents (the compute shader's in the order its atomics arrive);
// which patches split, and so every tally, is the same while no level
// reaches the capacity.
//
// It runs the programs WavefrontStage would build with the options of
// nativePhotonRefusal: where a scene needs another, the compute shader runs.
#pragma once

#include "bridge/layout/GpuLayouts.h"
#include "render/stages/NativePhotonTrace.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace eikon::render {

// The refinement's uniforms (tracer.wavefront; WavefrontStage::run).
struct NativeWavefrontSettings {
    unsigned gridCells = 0;
    unsigned maxDepth = 0;
    unsigned capacity = 0;  // patches a level holds (a multiple of 4)
    float splitTexels = 0.0f;
    float tearTexels = 0.0f;
    float minPower = 0.0f;
    float reflectionSplit = 0.0f;
};

// What the pass did, as layout::GpuWavefrontCounters counts it.
struct NativeWavefrontCounts {
    std::uint64_t finished = 0;
    std::uint64_t splits = 0;
    std::uint64_t atLimit = 0;
    std::uint64_t rays = 0;
};

class NativeWavefrontTrace {
public:
    // march: the photon pass's inputs the wavefront shares (the grid, its
    // textures on the host, receivers, emitters, sharp surfaces, power unit).
    NativeWavefrontTrace(const NativePhotonInputs& march, const NativeWavefrontSettings& settings,
                         std::size_t receiverTexels);
    ~NativeWavefrontTrace();

    // The wavefront the next chunks belong to (the uniforms of one
    // WavefrontStage::traceWavefront).
    void setWavefront(unsigned emitter, unsigned faces, int channel, int branch);
    // Seeds `seeds` patches from cell firstCell of the emission grid, traces
    // their corners and refines them level by level until none splits.
    void traceChunk(unsigned firstCell, unsigned seeds);

    // The threads' sums so far.
    NativePhotonTallies tallies() const;
    NativeWavefrontCounts counts() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace eikon::render
