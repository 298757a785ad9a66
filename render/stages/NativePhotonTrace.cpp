#include "render/stages/NativePhotonTrace.h"

#include "render/stages/NativeTextures.h"
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

namespace eikon::shader {
namespace {

using render::HostTexture3D;

// One photon of the pass: the shader's per-invocation state, its blocks and
// uniforms under their GLSL names, and its tallies as the thread's sums.
struct PhotonKernel {
    // The GLSL blocks' structs, under their GLSL names and types, expanded
    // from the same member lists as layout::GpuGrid, GpuReceiver, GpuEmitter
    // and GpuSharpSurface (bridge/layout/GpuLayouts.h; sizes checked below).
#define EIKON_GLSL_MEMBER(cppType, cppName, glslType, glslName, arrayLength) glslType glslName;
    struct GridBlock { EIKON_GPU_GRID(EIKON_GLSL_MEMBER) };
    struct Receiver { EIKON_GPU_RECEIVER(EIKON_GLSL_MEMBER) };
    struct Emitter { EIKON_GPU_EMITTER(EIKON_GLSL_MEMBER) };
    struct SharpSurface { EIKON_GPU_SHARP_SURFACE(EIKON_GLSL_MEMBER) };
#undef EIKON_GLSL_MEMBER
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
    uint photon_offset;
    uint photon_stride;
    uint checkerboard;
    uint seed;
    float power_cutoff;
    vec3 power_unit;
    render::NativePhotonTallies* tallies;

    // Per photon, as the shader's globals are per invocation.
    float channel_scale = 1.0f;
    float sharp_offset = 0.0f;
    uint inside_mask = 0u;
    uint surface_events = 0u;
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
#include "shaders/common/grid_box.glsl"
#include "shaders/common/receiver_hits.glsl"
#include "shaders/common/straight_flight.glsl"
#include "shaders/common/loop_budget.glsl"
#include "shaders/common/sharp_surface_crossings.glsl"
#include "shaders/common/integrators.glsl"
#include "shaders/common/ray_march_steps.glsl"
#include "shaders/common/spot_profile.glsl"
#include "shaders/common/suspended_photons.glsl"
#include "shaders/common/fluence_tracks.glsl"
#include "shaders/common/pass_loops.glsl"
#include "shaders/common/photon_tracer.glsl"
#pragma GCC diagnostic pop
};

static_assert(sizeof(PhotonKernel::GridBlock) == sizeof(layout::GpuGrid));
static_assert(sizeof(PhotonKernel::Receiver) == sizeof(layout::GpuReceiver));
static_assert(sizeof(PhotonKernel::Emitter) == sizeof(layout::GpuEmitter));
static_assert(sizeof(PhotonKernel::SharpSurface) == sizeof(layout::GpuSharpSurface));

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
    std::memcpy(&kernel.grid, &inputs.grid, sizeof kernel.grid);
    kernel.receivers = reinterpret_cast<const Kernel::Receiver*>(inputs.receivers.data());
    kernel.receiver_count = static_cast<unsigned>(inputs.receivers.size());
    kernel.emitters = reinterpret_cast<const Kernel::Emitter*>(inputs.emitters.data());
    kernel.emitter_count = static_cast<unsigned>(inputs.emitters.size());
    kernel.sharp_surfaces = reinterpret_cast<const Kernel::SharpSurface*>(inputs.surfaces.data());
    kernel.sharp_surface_count = static_cast<unsigned>(inputs.surfaces.size());
    const glm::ivec3 cells(inputs.grid.resolution);
    kernel.gradient_texture = {inputs.gradient, cells};
    kernel.step_structure = {inputs.steps, cells};
    kernel.dispersion = inputs.dispersion;
    kernel.step_length = inputs.stepLength;
    kernel.max_steps = inputs.maxSteps;
    kernel.photon_offset = static_cast<unsigned>(first);
    kernel.photon_stride = static_cast<unsigned>(stride);
    kernel.checkerboard = checkerboard ? 1u : 0u;
    kernel.seed = inputs.seed;
    kernel.power_cutoff = inputs.powerCutoff;
    kernel.power_unit = inputs.powerUnit;

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
