// The march of a light ray through the field grid, shared by the photon
// pass (photon_trace.comp) and the wavefront pass (wavefront_trace.comp):
// the uniforms and the ray's state it runs on; the march itself (the field
// of the ray's channel, the step policy, the integrator) is
// common/ray_march_steps.glsl, shared with C++. Includes grid_sampling.glsl,
// ray_step.glsl and step_size.glsl first. GLSL only.
//
// Program options (#defines set by the stage):
//   EIKON_INTEGRATOR       0 Euler, 1 leapfrog, 2 RK4
//   EIKON_OCTREE_STEPS     1: adaptive steps from the step structure
//   EIKON_SHARP_SURFACES   0 none, 1 spheres and boxes, 2 meshes or water too (common/sharp_surface_blocks.glsl)
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

uniform float step_length;  // uniform Δs, or the octree's Δs_min, in metres
uniform uint max_steps;     // trapped-ray cap

#if EIKON_OCTREE_STEPS
layout(binding = kStepTexture) uniform sampler3D step_structure;  // (octree level, step cap in m)
// The step structure's (octree level, step cap) at a cell.
vec2 step_node(ivec3 cell) { return texelFetch(step_structure, cell, 0).rg; }
#endif

#if EIKON_SHARP_SURFACES
#include "common/sharp_surface_blocks.glsl"
uint inside_mask = 0u;  // the sharp surfaces the ray is inside (common/sharp_surface_blocks.glsl)
#else
const uint inside_mask = 0u;  // no sharp surface: a ray is inside none
vec3 owned_medium_point(vec3 x, uint mask) { return x; }  // and no object owns a voxel's material
#endif

vec4 field_at(vec3 x);  // common/ray_march_steps.glsl
#include "common/integrators.glsl"
#include "common/ray_march_steps.glsl"
