#include "render/stages/NativeWavefrontTrace.h"

#include "shaders/common/cpp_shim.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstring>

// The program options of the one program the native pass compiles
// (wavefront_trace.comp's; nativePhotonRefusal in PhotonStage.cpp sends
// every scene that needs others to the compute shader).
#define EIKON_INTEGRATOR 1
#define EIKON_OCTREE_STEPS 1
#define EIKON_SHARP_SURFACES 1  // spheres and boxes: the triangle functions below are never called
#define EIKON_STORE_FLUENCE 0
#define EIKON_LATTICE_SOURCE 0
#define EIKON_LOOP_BUDGET 0

#include "render/stages/NativeTracerKernel.h"

namespace eikon::shader {
namespace {

using layout::kUnfollowed;

// A thread's sums: the tallies and the counters of its rays and patches.
struct ThreadSums {
    render::NativePhotonTallies tallies;
    render::NativeWavefrontCounts counts;
};

// One invocation of wavefront_trace.comp: the march's blocks and state
// (NativeTracerKernel), its own uniforms and its tallies as the thread's
// sums.
struct WavefrontKernel : NativeTracerKernel {
    using Corner = layout::GpuWavefrontCorner;
    using Patch = layout::GpuWavefrontPatch;

    // wavefront_trace.comp's uniforms.
    uint seeded_jobs;
    uint first_cell;
    uint seed_emitter;
    uint grid_cells;
    uint max_depth;
    uint capacity;
    float split_texels;
    float tear_texels;
    float min_power;
    float reflection_split;
    int channel;
    int branch;
    uint emission_faces;
    // The levels: Patches (read) and Children (written).
    const Patch* patches;
    Patch* children;
    ThreadSums* sums;

    // The counters of the shared text, into the thread's sums.
    void count_traced_ray() { ++sums->counts.rays; }
    void count_finished_patch() { ++sums->counts.finished; }
    void count_split_patch() { ++sums->counts.splits; }
    void count_limited_patch() { ++sums->counts.atLimit; }
    void count_march(uint steps, float max_invariant_error, uvec2 error_units) {
        sums->tallies.steps += steps;
        sums->tallies.maxInvariantBits = std::max(sums->tallies.maxInvariantBits, floatBitsToUint(max_invariant_error));
        sums->tallies.invariant += (std::uint64_t{error_units.y} << 32) + error_units.x;
    }
    // The deposits' 64-bit tallies (ADD_WIDE_UNITS below): the low word's
    // index over 2 is the sum's.
    std::uint64_t* power_tallies;
    std::uint64_t* receiver_tallies;
    static void add_wide_units(std::uint64_t* sums, uint low_word, uvec2 value) {
        sums[low_word / 2u] += (std::uint64_t{value.y} << 32) + value.x;
    }

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"  // bodies compiled out by the options
#pragma GCC diagnostic ignored "-Wshadow"            // GLSL parameters named as the ray's state
#include "shaders/common/fluence_tracks.glsl"
#include "shaders/common/pass_loops.glsl"
#include "shaders/common/wide_units.glsl"
#undef ADD_WIDE_UNITS
#define ADD_WIDE_UNITS(words, index, value) add_wide_units(words, index, value)
#include "shaders/common/wavefront_emission.glsl"
#include "shaders/common/wavefront_rays.glsl"
#include "shaders/common/wavefront_deposits.glsl"
#include "shaders/common/wavefront_patches.glsl"
#undef ADD_WIDE_UNITS
#pragma GCC diagnostic pop
};


}  // namespace
}  // namespace eikon::shader

namespace eikon::render {

struct NativeWavefrontTrace::Impl {
    using Kernel = shader::WavefrontKernel;
    Kernel kernel{};  // the uniforms; each iteration runs a copy, as a fresh invocation
    std::vector<layout::GpuWavefrontPatch> patches;   // the level being refined
    std::vector<layout::GpuWavefrontPatch> children;  // the level being written
    tbb::enumerable_thread_specific<shader::ThreadSums> sums;

    explicit Impl(const shader::ThreadSums& empty) : sums(empty) {}

    // body(invocation, index) for index in [0, count), in parallel.
    template <class Body>
    void each(std::size_t count, std::size_t grain, const Body& body) {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, grain),
                          [&](const tbb::blocked_range<std::size_t>& range) {
                              shader::ThreadSums& mine = sums.local();
                              for (std::size_t i = range.begin(); i != range.end(); ++i) {
                                  Kernel invocation = kernel;
                                  invocation.sums = &mine;
                                  invocation.power_tallies = mine.tallies.power;
                                  invocation.receiver_tallies = mine.tallies.receiver.data();
                                  body(invocation, static_cast<unsigned>(i));
                              }
                          });
    }

    // Mode 1 over the children: `jobs` rays.
    void trace(unsigned jobs, bool seeded) {
        kernel.seeded_jobs = seeded ? 1u : 0u;
        kernel.children = children.data();
        each(jobs, 16, [](Kernel& invocation, unsigned job) { invocation.trace_job(job); });
    }

    // Mode 2 over the patches: their children's slots claimed in the order
    // of the patches (a prefix sum), then each settled. Returns the patches
    // of the next level.
    unsigned refine(unsigned count) {
        std::swap(patches, children);
        kernel.patches = patches.data();
        std::vector<unsigned char> splitting(count);
        each(count, 64, [&](Kernel& invocation, unsigned index) {
            splitting[index] = invocation.wants_split(patches[index]) ? 1 : 0;
        });
        std::vector<unsigned> slots(count);
        std::uint64_t claimed = 0;
        for (unsigned index = 0; index < count; ++index) {
            const bool claims = kernel.claims_children(patches[index], splitting[index] != 0);
            slots[index] = claims && claimed < kernel.capacity ? static_cast<unsigned>(claimed) : kernel.capacity;
            if (claims) claimed += 4;
        }
        const auto next = static_cast<unsigned>(std::min<std::uint64_t>(claimed, kernel.capacity));
        children.assign(next, layout::GpuWavefrontPatch{});
        kernel.children = children.data();
        each(count, 64, [&](Kernel& invocation, unsigned index) {
            invocation.settle_patch(patches[index], splitting[index] != 0, slots[index]);
        });
        return next;
    }
};

NativeWavefrontTrace::NativeWavefrontTrace(const NativePhotonInputs& march, const NativeWavefrontSettings& settings,
                                           std::size_t receiverTexels) {
    shader::ThreadSums empty;
    empty.tallies.receiver.assign(3 * receiverTexels, 0);
    impl_ = std::make_unique<Impl>(empty);
    using Kernel = Impl::Kernel;
    Kernel& kernel = impl_->kernel;
    kernel.bindMarch(march);
    kernel.grid_cells = settings.gridCells;
    kernel.max_depth = settings.maxDepth;
    kernel.capacity = settings.capacity;
    kernel.split_texels = settings.splitTexels;
    kernel.tear_texels = settings.tearTexels;
    kernel.min_power = settings.minPower;
    kernel.reflection_split = settings.reflectionSplit;
}

NativeWavefrontTrace::~NativeWavefrontTrace() = default;

void NativeWavefrontTrace::setWavefront(unsigned emitter, unsigned faces, int channel, int branch) {
    Impl::Kernel& kernel = impl_->kernel;
    kernel.seed_emitter = emitter;
    kernel.emission_faces = faces;
    kernel.channel = channel;
    kernel.branch = branch;
}

void NativeWavefrontTrace::traceChunk(unsigned firstCell, unsigned seeds) {
    Impl& impl = *impl_;
    impl.kernel.first_cell = firstCell;
    impl.children.assign(seeds, layout::GpuWavefrontPatch{});
    impl.kernel.children = impl.children.data();
    impl.each(seeds, 256, [](Impl::Kernel& invocation, unsigned index) { invocation.seed(index); });
    impl.trace(3u * seeds, true);
    for (unsigned count = seeds; count > 0;) {
        count = impl.refine(count);
        if (count > 0) impl.trace(count / 4u * 3u, false);
    }
}

NativePhotonTallies NativeWavefrontTrace::tallies() const {
    NativePhotonTallies total;
    for (const shader::ThreadSums& thread : impl_->sums) total.add(thread.tallies);
    return total;
}

NativeWavefrontCounts NativeWavefrontTrace::counts() const {
    NativeWavefrontCounts total;
    for (const shader::ThreadSums& thread : impl_->sums) {
        total.finished += thread.counts.finished;
        total.splits += thread.counts.splits;
        total.atLimit += thread.counts.atLimit;
        total.rays += thread.counts.rays;
    }
    return total;
}

}  // namespace eikon::render
