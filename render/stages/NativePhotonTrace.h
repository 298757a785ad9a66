// The photon pass on the CPU: the very text of the compute shader's tracer
// (shaders/common/photon_tracer.glsl and what it includes), compiled as C++
// through cpp_shim.h and run as a TBB loop over photons. Each thread sums
// its photons' tallies into its own 64-bit integers — power, receiver
// texels and counts in the shader's fixed-point units — and the threads'
// sums are added: integer sums do not depend on the order they are taken
// in, so a pass gives the same bits run to run, and the same integers as
// the work groups' atomics give wherever its photons took the same paths.
//
// It runs the programs PhotonStage would build with the options of
// nativePhotonRefusal: where a scene needs another, the compute shader runs.
#pragma once

#include "bridge/layout/GpuLayouts.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace eikon::render {

// What the shader reads from its blocks, buffers, textures and uniforms.
struct NativePhotonInputs {
    layout::GpuGrid grid{};
    const glm::vec4* gradient = nullptr;  // (∇n, δn) per cell, x fastest
    const glm::vec4* steps = nullptr;     // the step structure per cell; null: uniform steps
    std::vector<layout::GpuReceiver> receivers;
    std::vector<layout::GpuEmitter> emitters;
    std::vector<layout::GpuSharpSurface> surfaces;  // spheres and boxes
    glm::vec3 dispersion{1.0f};
    float stepLength = 0.0f;
    unsigned maxSteps = 0;
    unsigned seed = 1;
    float powerCutoff = 1e-4f;
    glm::vec3 powerUnit{0.0f};
};

// A pass's tallies, in the units of layout::GpuPhotonStats and the
// ReceiverTallies buffer.
struct NativePhotonTallies {
    std::uint64_t power[3 * layout::kTallyCount] = {};  // [3·tally + channel]
    std::uint64_t photons[4] = {};                      // escaped, received, cut off, blocked
    std::uint64_t steps = 0;
    std::uint32_t maxInvariantBits = 0;  // float bits: non-negative floats order as their bits
    std::uint64_t deposits = 0;
    std::uint64_t invariant = 0;  // 2^-32 units
    std::uint64_t surfaces[2] = {};  // reflected, transmitted
    std::vector<std::uint64_t> receiver;  // per texel and channel

    void add(const NativePhotonTallies& other);
    // The statistics block as the shader leaves it.
    layout::GpuPhotonStats stats() const;
};

// Traces photons first, first + stride, … (count of them; checkerboard: the
// halves' checkerboards of strata, as PhotonStage::tracePhotons) into
// `tallies`, whose receiver tallies hold every texel of the receivers.
void tracePhotonsNative(const NativePhotonInputs& inputs, std::size_t first, std::size_t stride, std::size_t count,
                        bool checkerboard, NativePhotonTallies& tallies);

}  // namespace eikon::render
