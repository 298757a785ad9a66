// The scene's sharp surfaces as the tracers see them (GLSL only; the math is
// common/sharp_surfaces.glsl for spheres and boxes and
// common/sharp_triangle_surfaces.glsl for meshes and water, and a ray's
// crossings of them common/sharp_surface_crossings.glsl). C++ mirror:
// layout::GpuSharpSurface, filled by render/stages/SharpSurfaceBuffer. A ray keeps a bit per surface it is
// inside; the innermost object — the last in scene order holding the point —
// sets the index offset added to the graded field there.
//
// Program option EIKON_SHARP_SURFACES: 1 the scene's sharp surfaces are
// spheres and boxes only, 2 (where the includer does not say) meshes or
// water too (render/stages/SharpSurfaceBuffer, kindsOption).
#ifndef EIKON_SHARP_SURFACES
#define EIKON_SHARP_SURFACES 2
#endif
#include "common/sharp_triangle_surfaces.glsl"

#include "common/sharp_surface_list.glsl"

uniform uint sharp_surface_count;  // at most 32: one bit each in a ray's inside mask

#include "common/sharp_surface_crossings.glsl"
