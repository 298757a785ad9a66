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

// What a ray of unit direction d meets where a step ended on sharp surface
// k: the point put exactly on the surface, the unit normal facing the ray,
// the inside mask beyond it, the indices on either side — the graded field
// at the point plus each side's offset, δn scaled by `index_scale`
// (dispersion) — and the unpolarised Fresnel reflectance (1 under total
// internal reflection; 0 where the object's Fresnel reflection is off).
struct SurfaceEvent {
    vec3 x;
    vec3 facing;
    uint beyond_mask;
    float n_here;
    float n_beyond;
    float beyond_offset;
    float reflectance;
};

SurfaceEvent sharp_surface_event(uint k, vec3 x, vec3 d, uint inside_mask, float index_scale) {
    vec4 shape_a = sharp_surfaces[k].shape_a;
    vec4 shape_b = sharp_surfaces[k].shape_b;
    SurfaceEvent event;
    event.x = onto_surface(shape_a, shape_b, x);
    vec3 outward = surface_normal(shape_a, shape_b, event.x);
    event.facing = dot(d, outward) < 0.0f ? outward : -outward;
    event.beyond_mask = inside_mask ^ (1u << k);
    event.beyond_offset = sharp_index_offset(event.beyond_mask);
    float graded = sample_gradient_and_delta(event.x).w;
    event.n_here = reference_index() + index_scale * (graded + sharp_index_offset(inside_mask));
    event.n_beyond = reference_index() + index_scale * (graded + event.beyond_offset);
    event.reflectance = fresnel_reflectance(-dot(d, event.facing), event.n_here, event.n_beyond);
    if (event.reflectance < 1.0f && sharp_surfaces[k].optics.y < 0.5f) event.reflectance = 0.0f;
    return event;
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
