// The field grid as shaders see it: the GridBlock uniform (members:
// layout::GpuGrid) and the field textures, sampled trilinearly between cell
// centres with clamp-to-edge. GLSL only. A program sets EIKON_HAS_EXTINCTION,
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

const float EIKON_INFINITY = 1e30f;

float reference_index() { return grid.bounds_min.w; }

vec3 grid_uvw(vec3 x) {
    return (x - grid.bounds_min.xyz) / (grid.bounds_max.xyz - grid.bounds_min.xyz);
}

bool grid_contains(vec3 x) {
    return all(greaterThanEqual(x, grid.bounds_min.xyz)) && all(lessThanEqual(x, grid.bounds_max.xyz));
}

ivec3 grid_cell(vec3 x) {
    return clamp(ivec3(floor((x - grid.bounds_min.xyz) / grid.voxel_size.xyz)), ivec3(0), grid.resolution.xyz - 1);
}

int grid_linear_index(ivec3 cell) {
    return cell.x + grid.resolution.x * (cell.y + grid.resolution.y * cell.z);
}

// Parameters (t_enter, t_exit) of the straight ray x + t·d inside the grid
// box (slab method); t_enter > t_exit when it misses.
vec2 grid_ray_interval(vec3 x, vec3 d) {
    vec3 inverse = 1.0f / d;
    vec3 t0 = (grid.bounds_min.xyz - x) * inverse;
    vec3 t1 = (grid.bounds_max.xyz - x) * inverse;
    vec3 near = min(t0, t1);
    vec3 far = max(t0, t1);
    return vec2(max(max(near.x, near.y), near.z), min(min(far.x, far.y), far.z));
}

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
