// The scene's sharp surfaces as the tracers see them (GLSL only; the math is
// common/sharp_surfaces.glsl). C++ mirror: layout::GpuSharpSurface, filled
// by render/stages/SharpSurfaceBuffer. A ray keeps a bit per surface it is
// inside; the innermost object — the last in scene order holding the point —
// sets the index offset added to the graded field there.
struct SharpSurface {
    vec4 shape_a;  // xyz sphere centre or box min; w kind (0 sphere, 1 box)
    vec4 shape_b;  // x sphere radius, or xyz box max
    vec4 optics;   // x n_object − n_ref; y 1 if Fresnel reflects
};
layout(std430, binding = kSharpSurfaces) readonly buffer SharpSurfaces { SharpSurface sharp_surfaces[]; };

uniform uint sharp_surface_count;  // at most 32: one bit each in a ray's inside mask

// The bits of the surfaces whose inside holds x.
uint inside_mask_at(vec3 x) {
    uint mask = 0u;
    for (uint k = 0u; k < sharp_surface_count; ++k)
        if (inside_shape(sharp_surfaces[k].shape_a, sharp_surfaces[k].shape_b, x)) mask |= 1u << k;
    return mask;
}

// δn the sharp objects add where a ray inside exactly the surfaces of `mask` is.
float sharp_index_offset(uint mask) {
    for (uint k = sharp_surface_count; k > 0u; --k)
        if ((mask & (1u << (k - 1u))) != 0u) return sharp_surfaces[k - 1u].optics.x;
    return 0.0f;
}

// The first surface a step from x along the unit d meets within reach
// (index −1: none), for a ray inside the surfaces of `mask`.
struct SurfaceCrossing {
    int surface;
    float distance;
};

SurfaceCrossing nearest_surface_crossing(vec3 x, vec3 d, uint mask, float reach, float t_min) {
    SurfaceCrossing crossing;
    crossing.surface = -1;
    crossing.distance = reach;
    for (uint k = 0u; k < sharp_surface_count; ++k) {
        float t = surface_crossing(sharp_surfaces[k].shape_a, sharp_surfaces[k].shape_b, x, d,
                                   (mask & (1u << k)) != 0u, t_min);
        if (t < crossing.distance) {
            crossing.surface = int(k);
            crossing.distance = t;
        }
    }
    return crossing;
}
