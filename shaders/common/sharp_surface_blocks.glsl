// The scene's sharp surfaces as the tracers see them (GLSL only; the math is
// common/sharp_surfaces.glsl for spheres and boxes and
// common/sharp_distance_surfaces.glsl for meshes and water). C++ mirror:
// layout::GpuSharpSurface, filled by render/stages/SharpSurfaceBuffer. A ray keeps a bit per surface it is
// inside; the innermost object — the last in scene order holding the point —
// sets the index offset added to the graded field there.
#include "common/sharp_distance_surfaces.glsl"

struct SharpSurface {
    vec4 shape_a;  // xyz sphere centre, or box or distance bounds min; w kind (kSharpSphere, kSharpBox, kSharpDistance)
    vec4 shape_b;  // x sphere radius, or xyz box or distance bounds max; w distance layer
    vec4 optics;   // x n_object − n_ref; y 1 if Fresnel reflects
};
layout(std430, binding = kSharpSurfaces) readonly buffer SharpSurfaces { SharpSurface sharp_surfaces[]; };

uniform uint sharp_surface_count;  // at most 32: one bit each in a ray's inside mask

bool is_distance_surface(uint k) { return surface_kind(sharp_surfaces[k].shape_a) == kSharpDistance; }

// The bits of the surfaces whose inside holds x.
uint inside_mask_at(vec3 x) {
    uint mask = 0u;
    for (uint k = 0u; k < sharp_surface_count; ++k) {
        vec4 shape_a = sharp_surfaces[k].shape_a;
        vec4 shape_b = sharp_surfaces[k].shape_b;
        bool inside = is_distance_surface(k) ? inside_distance_surface(shape_a, shape_b, x)
                                             : inside_shape(shape_a, shape_b, x);
        if (inside) mask |= 1u << k;
    }
    return mask;
}

// δn the sharp objects add where a ray inside exactly the surfaces of `mask` is.
float sharp_index_offset(uint mask) {
    for (uint k = sharp_surface_count; k > 0u; --k)
        if ((mask & (1u << (k - 1u))) != 0u) return sharp_surfaces[k - 1u].optics.x;
    return 0.0f;
}

// What a ray of unit direction d meets where a step ended on sharp surface
// k: where it goes on when reflected and when transmitted (the point put
// exactly on a sphere or box; a clearance off either side of a mesh or water
// surface, whose φ is only known to float precision), the unit normal facing the ray,
// the inside mask beyond it, the indices on either side — the graded field
// at the point plus each side's offset, δn scaled by `index_scale`
// (dispersion) — and the unpolarised Fresnel reflectance (1 under total
// internal reflection; 0 where the object's Fresnel reflection is off).
struct SurfaceEvent {
    vec3 x_reflected;
    vec3 x_transmitted;
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
    bool distance = is_distance_surface(k);
    vec3 on = distance ? x : onto_surface(shape_a, shape_b, x);
    vec3 outward = distance ? distance_surface_normal(shape_b, on) : surface_normal(shape_a, shape_b, on);
    event.facing = dot(d, outward) < 0.0f ? outward : -outward;
    float clearance = distance ? distance_surface_clearance() : 0.0f;
    event.x_reflected = on + clearance * event.facing;
    event.x_transmitted = on - clearance * event.facing;
    event.beyond_mask = inside_mask ^ (1u << k);
    event.beyond_offset = sharp_index_offset(event.beyond_mask);
    float graded = sample_gradient_and_delta(on).w;
    event.n_here = reference_index() + index_scale * (graded + sharp_index_offset(inside_mask));
    event.n_beyond = reference_index() + index_scale * (graded + event.beyond_offset);
    event.reflectance = fresnel_reflectance(-dot(d, event.facing), event.n_here, event.n_beyond);
    if (event.reflectance < 1.0f && sharp_surfaces[k].optics.y < 0.5f) event.reflectance = 0.0f;
    return event;
}

// The first surface a step from x along the unit d meets within reach
// (index −1: none), for a ray inside the surfaces of `mask`; with none, the
// distance is the reach, or less where the search for a mesh or water
// surface ran out of probes: the step ends there.
struct SurfaceCrossing {
    int surface;
    float distance;
};

SurfaceCrossing nearest_surface_crossing(vec3 x, vec3 d, uint mask, float reach, float t_min) {
    SurfaceCrossing crossing;
    crossing.surface = -1;
    crossing.distance = reach;
    for (uint k = 0u; k < sharp_surface_count; ++k) {
        bool inside = (mask & (1u << k)) != 0u;
        vec4 shape_a = sharp_surfaces[k].shape_a;
        vec4 shape_b = sharp_surfaces[k].shape_b;
        int surface = int(k);
        float t;
        if (is_distance_surface(k)) {
            vec2 found = distance_surface_crossing(shape_a, shape_b, x, d, inside, crossing.distance, t_min);
            t = found.x;
            if (found.y < 0.5f) surface = -1;
        } else {
            t = surface_crossing(shape_a, shape_b, x, d, inside, t_min);
        }
        if (t < crossing.distance) {
            crossing.surface = surface;
            crossing.distance = t;
        }
    }
    return crossing;
}
