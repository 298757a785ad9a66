// Test probe: evaluates the shared math of shaders/common on inputs from a
// buffer, so tests can compare the GPU's results with the same functions
// compiled as C++ (tests/integration/test_shared_math.cpp). Layout per case:
// 4 vec4 inputs followed by 4 vec4 outputs. Not a production shader: tests
// compile it with gl::compileComputeProgramFromSource, which resolves its
// includes from the embedded shaders/, and define EIKON_PROBE_BINDING.
layout(local_size_x = 64) in;

#include "common/random.glsl"
#include "common/ray_step.glsl"
#include "common/attenuation.glsl"
#include "common/phase.glsl"
#include "common/sampling.glsl"
#include "common/receiver.glsl"

layout(std430, binding = EIKON_PROBE_BINDING) buffer Probe { vec4 probe[]; };

uniform uint case_count;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= case_count) return;
    vec4 a = probe[8u * i + 0u];  // x, n
    vec4 b = probe[8u * i + 1u];  // v, ds
    vec4 c = probe[8u * i + 2u];  // ∇n, g
    vec4 d = probe[8u * i + 3u];  // κ, cosθ

    vec3 x = a.xyz;
    vec3 v = b.xyz;
    vec3 x_lost = vec3(0.0f);
    eikonal_euler_step(x, x_lost, v, a.w, c.xyz, b.w);
    probe[8u * i + 4u] = vec4(x, eikonal_invariant_error(v, a.w));
    probe[8u * i + 5u] = vec4(v, henyey_greenstein(d.w, c.w));
    probe[8u * i + 6u] = vec4(beer_lambert_transmittance(d.xyz, b.w), random_uniform(i, 7u, 3u));
    vec3 axis = normalize(c.xyz + vec3(0.0f, 0.0f, 1e-3f));
    vec3 tangent = normalize(cross(axis, abs(axis.x) < 0.9f ? vec3(1.0f, 0.0f, 0.0f) : vec3(0.0f, 1.0f, 0.0f)));
    vec3 cone = sample_cone(axis, tangent, cross(axis, tangent), 0.5f, fract(a.x), fract(a.y));
    probe[8u * i + 7u] = vec4(attenuated_track_length(d.xyz, b.w).x, cone.x, cone.y, cone.z);
}
