// What every native light pass's kernel holds before its own shared text:
// the GLSL blocks a march reads (grid, receivers, emitters, sharp surfaces)
// under their GLSL names, the march's textures and uniforms, a ray's
// per-invocation state, and stand-ins for the triangle searches, which the
// native passes never reach (they take spheres and boxes only:
// nativePhotonRefusal in PhotonStage.cpp). NativePhotonTrace.cpp and
// NativeWavefrontTrace.cpp derive their kernels from it and include the
// text of their own pass into them (docs/architecture.md, "photons on either
// device"). Include it after shaders/common/cpp_shim.h and the program
// options.
#pragma once

#include "render/stages/NativePhotonTrace.h"
#include "render/stages/NativeTextures.h"

#include <cstring>

namespace eikon::shader {

struct NativeTracerKernel {
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
    // never reached.
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
    render::HostTexture3D<vec4> gradient_texture;
    render::HostTexture3D<vec4> step_structure;
    vec3 dispersion;
    float step_length;
    uint max_steps;
    vec3 power_unit;

    // Per ray, as the shader's globals are per invocation.
    float channel_scale = 1.0f;
    float sharp_offset = 0.0f;
    uint inside_mask = 0u;
    uint deposits = 0u;

    // The march's blocks, textures and uniforms, from the pass's inputs.
    void bindMarch(const render::NativePhotonInputs& march) {
        std::memcpy(&grid, &march.grid, sizeof grid);
        receivers = reinterpret_cast<const Receiver*>(march.receivers.data());
        receiver_count = static_cast<uint>(march.receivers.size());
        emitters = reinterpret_cast<const Emitter*>(march.emitters.data());
        emitter_count = static_cast<uint>(march.emitters.size());
        sharp_surfaces = reinterpret_cast<const SharpSurface*>(march.surfaces.data());
        sharp_surface_count = static_cast<uint>(march.surfaces.size());
        const glm::ivec3 cells(march.grid.resolution);
        gradient_texture = {march.gradient, cells};
        step_structure = {march.steps, cells};
        dispersion = march.dispersion;
        step_length = march.stepLength;
        max_steps = march.maxSteps;
        power_unit = march.powerUnit;
    }

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

    // The shared text of the march itself (grid_uvw above, the box, the
    // receivers, sharp surfaces, integrators and steps); the derived kernel
    // includes its pass's text after it.
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
#pragma GCC diagnostic pop
};

static_assert(sizeof(NativeTracerKernel::GridBlock) == sizeof(layout::GpuGrid));
static_assert(sizeof(NativeTracerKernel::Receiver) == sizeof(layout::GpuReceiver));
static_assert(sizeof(NativeTracerKernel::Emitter) == sizeof(layout::GpuEmitter));
static_assert(sizeof(NativeTracerKernel::SharpSurface) == sizeof(layout::GpuSharpSurface));

}  // namespace eikon::shader
