#include "render/stages/NativeWavefrontTrace.h"

#include "render/stages/NativeTextures.h"
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

namespace eikon::shader {
namespace {

using layout::kUnfollowed;
using render::HostTexture3D;

// A thread's sums: the tallies and the counters of its rays and patches.
struct ThreadSums {
    render::NativePhotonTallies tallies;
    render::NativeWavefrontCounts counts;
};

// One invocation of wavefront_trace.comp: its blocks and uniforms under
// their GLSL names, its per-invocation state, and its tallies as the
// thread's sums.
struct WavefrontKernel {
    // The GLSL blocks' structs, expanded from the member lists of
    // bridge/layout/GpuLayouts.h (sizes checked below); Corner and Patch name
    // their members as GLSL does.
#define EIKON_GLSL_MEMBER(cppType, cppName, glslType, glslName, arrayLength) glslType glslName;
    struct GridBlock { EIKON_GPU_GRID(EIKON_GLSL_MEMBER) };
    struct Receiver { EIKON_GPU_RECEIVER(EIKON_GLSL_MEMBER) };
    struct Emitter { EIKON_GPU_EMITTER(EIKON_GLSL_MEMBER) };
    struct SharpSurface { EIKON_GPU_SHARP_SURFACE(EIKON_GLSL_MEMBER) };
#undef EIKON_GLSL_MEMBER
    using Corner = layout::GpuWavefrontCorner;
    using Patch = layout::GpuWavefrontPatch;
    // common/sharp_triangle_surfaces.glsl's, whose functions below are
    // never reached: the native pass takes spheres and boxes only.
    struct TriangleTrace {
        float t;
        int triangle;
        vec2 uv;
        int hits;
    };

    GridBlock grid;
    const Receiver* receivers;
    uint receiver_count;
    const Emitter* emitters;
    uint emitter_count;
    const SharpSurface* sharp_surfaces;
    uint sharp_surface_count;
    HostTexture3D<vec4> gradient_texture;
    HostTexture3D<vec4> step_structure;
    vec3 dispersion;
    float step_length;
    uint max_steps;
    vec3 power_unit;
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

    // Per ray, as the shader's globals are per invocation.
    float channel_scale = 1.0f;
    float sharp_offset = 0.0f;
    uint inside_mask = 0u;
    uint deposits = 0u;

    // common/grid_sampling.glsl's textures.
    vec4 sample_gradient_and_delta(vec3 x) { return gradient_texture.linear(grid_uvw(x)); }
    vec3 sample_extinction(vec3) { return vec3(0.0f); }
    vec3 sample_scattering(vec3) { return vec3(0.0f); }
    // common/ray_march.glsl's step structure.
    vec2 step_node(ivec3 cell) { return vec2(step_structure.fetch(cell)); }

    bool inside_triangle_surface(vec4, vec3) { return false; }
    TriangleTrace triangle_surface_crossing(vec4, vec3, vec3, float, float) { return {0.0f, -1, vec2(0.0f), 0}; }
    vec3 onto_triangle(int, vec3 p) { return p; }
    vec3 triangle_facet_normal(int) { return vec3(0.0f); }
    vec3 triangle_facing_normal(int, vec2, vec3, vec3 facet_facing, float, float) { return facet_facing; }
    float triangle_surface_clearance() { return 0.0f; }

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
#include "shaders/common/grid_box.glsl"
#include "shaders/common/receiver_hits.glsl"
#include "shaders/common/straight_flight.glsl"
#include "shaders/common/loop_budget.glsl"
#include "shaders/common/sharp_surface_crossings.glsl"
#include "shaders/common/integrators.glsl"
#include "shaders/common/ray_march_steps.glsl"
#include "shaders/common/spot_profile.glsl"
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

static_assert(sizeof(WavefrontKernel::GridBlock) == sizeof(layout::GpuGrid));
static_assert(sizeof(WavefrontKernel::Receiver) == sizeof(layout::GpuReceiver));
static_assert(sizeof(WavefrontKernel::Emitter) == sizeof(layout::GpuEmitter));
static_assert(sizeof(WavefrontKernel::SharpSurface) == sizeof(layout::GpuSharpSurface));

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
    std::memcpy(&kernel.grid, &march.grid, sizeof kernel.grid);
    kernel.receivers = reinterpret_cast<const Kernel::Receiver*>(march.receivers.data());
    kernel.receiver_count = static_cast<unsigned>(march.receivers.size());
    kernel.emitters = reinterpret_cast<const Kernel::Emitter*>(march.emitters.data());
    kernel.emitter_count = static_cast<unsigned>(march.emitters.size());
    kernel.sharp_surfaces = reinterpret_cast<const Kernel::SharpSurface*>(march.surfaces.data());
    kernel.sharp_surface_count = static_cast<unsigned>(march.surfaces.size());
    const glm::ivec3 cells(march.grid.resolution);
    kernel.gradient_texture = {march.gradient, cells};
    kernel.step_structure = {march.steps, cells};
    kernel.dispersion = march.dispersion;
    kernel.step_length = march.stepLength;
    kernel.max_steps = march.maxSteps;
    kernel.power_unit = march.powerUnit;
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
