// The field grid as shaders see it: the GridBlock uniform (members:
// layout::GpuGrid) and the field textures, sampled trilinearly between cell
// centres with clamp-to-edge. GLSL only; the box's geometry is shared
// (common/grid_box.glsl), and render/stages/NativeTextures.h samples the
// textures' host copies for the native light pass. A program sets EIKON_HAS_EXTINCTION,
// EIKON_HAS_SCATTERING and EIKON_HAS_EMISSION to 1 only when the scene has
// such fields.
#ifndef EIKON_HAS_EXTINCTION
#define EIKON_HAS_EXTINCTION 0
#endif
#ifndef EIKON_HAS_SCATTERING
#define EIKON_HAS_SCATTERING 0
#endif
#ifndef EIKON_HAS_EMISSION
#define EIKON_HAS_EMISSION 0
#endif

layout(std140, binding = kGridBlock) uniform GridBlock { EIKON_GPU_GRID } grid;

layout(binding = kGradientTexture) uniform sampler3D gradient_texture;  // (∇n in 1/m, δn)
#if EIKON_HAS_EXTINCTION
layout(binding = kExtinctionTexture) uniform sampler3D extinction_texture;  // κ rgb in 1/m
#endif
#if EIKON_HAS_SCATTERING
layout(binding = kScatteringTexture) uniform sampler3D scattering_texture;  // σs rgb in 1/m
#endif
#if EIKON_HAS_EMISSION
layout(binding = kEmissionTexture) uniform sampler3D emission_texture;  // ε rgb in W/(m³·sr)
#endif

#include "common/grid_box.glsl"

// (∇n, δn) at x.
vec4 sample_gradient_and_delta(vec3 x) {
    return textureLod(gradient_texture, grid_uvw(x), 0.0f);
}

vec3 sample_extinction(vec3 x) {
#if EIKON_HAS_EXTINCTION
    return textureLod(extinction_texture, grid_uvw(x), 0.0f).rgb;
#else
    return vec3(0.0f);
#endif
}

vec3 sample_scattering(vec3 x) {
#if EIKON_HAS_SCATTERING
    return textureLod(scattering_texture, grid_uvw(x), 0.0f).rgb;
#else
    return vec3(0.0f);
#endif
}

// Emitted radiance per unit length ε at x ([Ihrke07] §3, L_e).
vec3 sample_emission(vec3 x) {
#if EIKON_HAS_EMISSION
    return textureLod(emission_texture, grid_uvw(x), 0.0f).rgb;
#else
    return vec3(0.0f);
#endif
}
