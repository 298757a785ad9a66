#include "render/stages/NativePhotonTrace.h"

#include "shaders/common/cpp_shim.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstring>

// The program options of the one program the native pass compiles
// (photon_trace.comp's; nativePhotonRefusal in PhotonStage.cpp sends every
// scene that needs others to the compute shader).
#define EIKON_INTEGRATOR 1
#define EIKON_OCTREE_STEPS 1
#define EIKON_SHARP_SURFACES 1  // spheres and boxes: the triangle functions below are never called
#define EIKON_RENORMALIZE 0
#define EIKON_DISPERSION 0
#define EIKON_BOUNCE 0
#define EIKON_BARE_MARCH 0
#define EIKON_STORE_FLUENCE 0
#define EIKON_LATTICE_SOURCE 0
#define EIKON_VOLUME_GLOW 0
#define EIKON_LOOP_BUDGET 0

#include "render/stages/NativeTracerKernel.h"

namespace eikon::shader {
namespace {

// One photon of the pass: the march's blocks and state
// (NativeTracerKernel), its own uniforms and its tallies as the thread's sums.
struct PhotonKernel : NativeTracerKernel {
    uint photon_offset;
    uint photon_stride;
    uint checkerboard;
    uint seed;
    float power_cutoff;
    render::NativePhotonTallies* tallies;
    uint surface_events = 0u;  // per photon, as the shader's global

    // The tallies of common/photon_tracer.glsl, into the thread's sums.
    void add_group_power(int index, uint units) { tallies->power[index] += units; }
    void add_wide_receiver(uint low_word, uint value) { tallies->receiver[low_word / 2u] += value; }
    void count_surface_event(int kind) { ++tallies->surfaces[kind]; }
    void count_photon(int fate) { ++tallies->photons[fate - kEscaped]; }
    void count_march(uint marched, float max_invariant_error, uint deposited, uvec2 error_units) {
        tallies->steps += marched;
        tallies->maxInvariantBits = std::max(tallies->maxInvariantBits, floatBitsToUint(max_invariant_error));
        tallies->deposits += deposited;
        tallies->invariant += (std::uint64_t{error_units.y} << 32) + error_units.x;
    }
    // Nothing is recorded (EIKON_RECORD_PATHS and EIKON_RECORD_ENDS are 0).
    void record_vertex(uint, uint, vec3, vec3) {}
    void record_end(uint, vec3, int, int, vec3) {}

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"  // bodies compiled out by the options
#pragma GCC diagnostic ignored "-Wshadow"            // GLSL parameters named as the ray's state
#include "shaders/common/suspended_photons.glsl"
#include "shaders/common/fluence_tracks.glsl"
#include "shaders/common/pass_loops.glsl"
#include "shaders/common/photon_tracer.glsl"
#pragma GCC diagnostic pop
};

}  // namespace
}  // namespace eikon::shader

namespace eikon::render {

void NativePhotonTallies::add(const NativePhotonTallies& other) {
    for (unsigned i = 0; i < 3 * layout::kTallyCount; ++i) power[i] += other.power[i];
    for (int i = 0; i < 4; ++i) photons[i] += other.photons[i];
    steps += other.steps;
    maxInvariantBits = std::max(maxInvariantBits, other.maxInvariantBits);
    deposits += other.deposits;
    invariant += other.invariant;
    for (int i = 0; i < 2; ++i) surfaces[i] += other.surfaces[i];
    if (receiver.size() < other.receiver.size()) receiver.resize(other.receiver.size(), 0);
    for (std::size_t i = 0; i < other.receiver.size(); ++i) receiver[i] += other.receiver[i];
}

layout::GpuPhotonStats NativePhotonTallies::stats() const {
    layout::GpuPhotonStats gpu{};
    auto low = [](std::uint64_t value) { return static_cast<std::uint32_t>(value); };
    auto high = [](std::uint64_t value) { return static_cast<std::uint32_t>(value >> 32); };
    for (unsigned tally = 0; tally < layout::kTallyCount; ++tally)
        for (int c = 0; c < 3; ++c) {
            gpu.power[tally][c][0] = low(power[3 * tally + c]);
            gpu.power[tally][c][1] = high(power[3 * tally + c]);
        }
    gpu.photons = glm::uvec4(low(photons[0]), low(photons[1]), low(photons[2]), low(photons[3]));
    gpu.steps = glm::uvec4(low(steps), high(steps), maxInvariantBits, 0u);
    gpu.deposits = glm::uvec4(low(deposits), high(deposits), 0u, 0u);
    gpu.invariant = glm::uvec4(low(invariant), high(invariant), 0u, 0u);
    gpu.surfaces = glm::uvec4(low(surfaces[0]), low(surfaces[1]), 0u, 0u);
    return gpu;
}

void tracePhotonsNative(const NativePhotonInputs& inputs, std::size_t first, std::size_t stride, std::size_t count,
                        bool checkerboard, NativePhotonTallies& tallies) {
    using Kernel = shader::PhotonKernel;
    Kernel kernel{};
    kernel.bindMarch(inputs);
    kernel.photon_offset = static_cast<unsigned>(first);
    kernel.photon_stride = static_cast<unsigned>(stride);
    kernel.checkerboard = checkerboard ? 1u : 0u;
    kernel.seed = inputs.seed;
    kernel.power_cutoff = inputs.powerCutoff;

    NativePhotonTallies empty;
    empty.receiver.assign(tallies.receiver.size(), 0);
    tbb::enumerable_thread_specific<NativePhotonTallies> threadTallies(empty);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 256), [&](const tbb::blocked_range<std::size_t>& ids) {
        NativePhotonTallies& mine = threadTallies.local();
        for (std::size_t id = ids.begin(); id != ids.end(); ++id) {
            Kernel photon = kernel;  // a fresh invocation's state
            photon.tallies = &mine;
            photon.trace_photon(static_cast<unsigned>(id));
        }
    });
    for (const NativePhotonTallies& thread : threadTallies) tallies.add(thread);
}

}  // namespace eikon::render
