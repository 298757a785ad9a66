// The march of a light ray through the field grid, shared by the photon
// pass (photon_trace.comp) and the wavefront pass (wavefront_trace.comp):
// the field (∇n, n) of the ray's channel with the offset of the sharp
// objects it is inside, the step policy and the integrator. Includes
// grid_sampling.glsl, ray_step.glsl and step_size.glsl first. GLSL only.
//
// Program options (#defines set by the stage):
//   EIKON_INTEGRATOR       0 Euler, 1 leapfrog, 2 RK4
//   EIKON_OCTREE_STEPS     1: adaptive steps from the step structure
//   EIKON_SHARP_SURFACES   1: the scene has sharp surfaces (common/sharp_surface_blocks.glsl)
#ifndef EIKON_INTEGRATOR
#define EIKON_INTEGRATOR 1
#endif
#ifndef EIKON_OCTREE_STEPS
#define EIKON_OCTREE_STEPS 0
#endif
#ifndef EIKON_SHARP_SURFACES
#define EIKON_SHARP_SURFACES 0
#endif

uniform vec3 dispersion;  // per-channel scale of δn
float channel_scale = 1.0f;  // this ray's scale (dispersion)
float sharp_offset = 0.0f;   // δn the sharp objects the ray is inside add to the graded field

// (∇n, n) for this ray's channel; used by the integrators.
vec4 field_at(vec3 x) {
    vec4 sample_ = sample_gradient_and_delta(x);
    return vec4(channel_scale * sample_.xyz, reference_index() + channel_scale * (sample_.w + sharp_offset));
}

#if EIKON_SHARP_SURFACES
#include "common/sharp_surface_blocks.glsl"
#endif

#include "common/integrators.glsl"

uniform float step_length;  // uniform Δs, or the octree's Δs_min, in metres
uniform uint max_steps;     // trapped-ray cap

#if EIKON_OCTREE_STEPS
layout(binding = kStepTexture) uniform sampler3D step_structure;  // (octree level, step cap in m)
#endif
float next_step(vec3 x, vec3 v) {
#if EIKON_OCTREE_STEPS
    vec2 node = texelFetch(step_structure, grid_cell(x), 0).rg;
    return octree_step(x, normalize(v), grid.bounds_min.xyz, grid.voxel_size.xyz, node.x, step_length, node.y);
#else
    return step_length;
#endif
}

void integrate(INOUT(vec3) x, INOUT(vec3) x_lost, INOUT(vec3) v, INOUT(vec4) field, float ds) {
#if EIKON_INTEGRATOR == 0
    integrate_euler(x, x_lost, v, field, ds);
#elif EIKON_INTEGRATOR == 1
    integrate_leapfrog(x, x_lost, v, field, ds);
#else
    integrate_rk4(x, x_lost, v, field, ds);
#endif
}

#if EIKON_SHARP_SURFACES
uint inside_mask = 0u;  // the sharp surfaces the ray is inside (common/sharp_surface_blocks.glsl)

// The ray's sharp surfaces at x, when it enters the grid or starts there.
void enter_sharp_region(vec3 x) {
    inside_mask = inside_mask_at(x);
    sharp_offset = sharp_index_offset(inside_mask);
}
#endif
