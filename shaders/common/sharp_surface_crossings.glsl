// Where a ray crosses the scene's sharp surfaces and what it meets there.
// Shared by GLSL and C++: the includer declares `sharp_surfaces` (struct
// SharpSurface, common/sharp_surface_list.glsl) and `sharp_surface_count`
// (GLSL: common/sharp_surface_blocks.glsl; C++:
// render/stages/NativePhotonTrace.cpp) and the triangle surfaces' functions
// (common/sharp_triangle_surfaces.glsl); needs common/sharp_surfaces.glsl,
// common/fresnel.glsl and common/grid_box.glsl.

// Program option EIKON_SHARP_SURFACES (1 spheres and boxes only, 2 meshes or
// water too; common/sharp_surface_blocks.glsl): under 2, no triangle
// surface exists, and the compiler drops their searches.
bool is_triangle_surface(uint k) {
    return EIKON_SHARP_SURFACES == 2 && surface_kind(sharp_surfaces[k].shape_a) == kSharpTriangles;
}

// The bits of the surfaces whose inside holds x.
uint inside_mask_at(vec3 x) {
    uint mask = 0u;
    for (uint k = 0u; k < sharp_surface_count; ++k) {
        vec4 shape_a = sharp_surfaces[k].shape_a;
        vec4 shape_b = sharp_surfaces[k].shape_b;
        bool inside = is_triangle_surface(k) ? inside_triangle_surface(shape_b, x) : inside_shape(shape_a, shape_b, x);
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

// x, moved off every sphere and box it lies within `margin` of, to `margin`
// off it on the side `mask` says it is (off_the_surface); meshes and water
// leave it where it is.
vec3 off_sharp_surfaces(vec3 x, uint mask, float margin) {
    vec3 p = x;
    for (uint k = 0u; k < sharp_surface_count; ++k) {
        if (is_triangle_surface(k)) continue;
        p = off_the_surface(sharp_surfaces[k].shape_a, sharp_surfaces[k].shape_b, p, (mask & (1u << k)) != 0u, margin);
    }
    return p;
}

// Where a ray inside exactly the surfaces of `mask` reads the grid's
// voxelised material (κ, σs, g, ε) at x. A sharp object's extinction and
// scattering are painted into the voxels it covers (sim/voxelize/
// Compositor), so a voxel its surface cuts blends both sides: read there, a
// ray's attenuation and glow would end at voxel faces, not at the surface
// the ray crosses exactly. Near a sphere or box the material is read off it,
// on the ray's side, by the reach of a trilinear read (1.5 voxels along each
// axis), where every voxel read lies wholly on that side.
// (Without sharp surfaces common/ray_march.glsl stands in: x itself.)
vec3 owned_medium_point(vec3 x, uint mask) {
#if EIKON_HAS_EXTINCTION || EIKON_HAS_SCATTERING || EIKON_HAS_EMISSION
    return off_sharp_surfaces(x, mask, 1.5f * length(xyz_of(grid.voxel_size)));
#else
    return x;  // nothing voxelised is read
#endif
}

// The first surface a step from x along the unit d meets within reach
// (index −1: none; the distance is then the reach), for a ray inside the
// surfaces of `mask`; on a mesh, the triangle and its barycentrics.
struct SurfaceCrossing {
    int surface;
    float distance;
    int triangle;
    vec2 uv;
};

SurfaceCrossing no_surface_crossing(float reach) {
    SurfaceCrossing crossing;
    crossing.surface = -1;
    crossing.distance = reach;
    crossing.triangle = -1;
    crossing.uv = vec2(0.0f);
    return crossing;
}

// The nearer of `crossing` and the first facet of a mesh or water surface
// along x + t·d before it.
SurfaceCrossing nearest_triangle_crossing(SurfaceCrossing crossing, vec3 x, vec3 d) {
    for (uint k = 0u; k < sharp_surface_count; ++k) {
        if (!is_triangle_surface(k)) continue;
        // No t_min: a ray leaves a facet a clearance off it, on the side it
        // goes on to, so it cannot meet that facet again, and a neighbour
        // may be nearer than any t_min at an edge.
        TriangleTrace hit = triangle_surface_crossing(sharp_surfaces[k].shape_b, x, d, crossing.distance, 0.0f);
        if (hit.triangle >= 0) {
            crossing.surface = int(k);
            crossing.distance = hit.t;
            crossing.triangle = hit.triangle;
            crossing.uv = hit.uv;
        }
    }
    return crossing;
}

// The nearer of `crossing` and the first sphere or box along x + t·d.
SurfaceCrossing nearest_shape_crossing(SurfaceCrossing crossing, vec3 x, vec3 d, uint mask, float t_min) {
    for (uint k = 0u; k < sharp_surface_count; ++k) {
        if (is_triangle_surface(k)) continue;
        float t = surface_crossing(sharp_surfaces[k].shape_a, sharp_surfaces[k].shape_b, x, d,
                                   (mask & (1u << k)) != 0u, t_min);
        if (t < crossing.distance) {
            crossing.surface = int(k);
            crossing.distance = t;
            crossing.triangle = -1;
        }
    }
    return crossing;
}

SurfaceCrossing nearest_surface_crossing(vec3 x, vec3 d, uint mask, float reach, float t_min) {
    return nearest_shape_crossing(nearest_triangle_crossing(no_surface_crossing(reach), x, d), x, d, mask, t_min);
}

// What a ray of unit direction d meets where a step ended at `crossing`:
// where it goes on when reflected and when transmitted (the point put
// exactly on a sphere or box; on a mesh, onto the facet's plane and a
// clearance off either side, since the next search must not meet the same
// facet again), the unit normal facing the ray, the inside mask beyond it,
// the indices on either side — the graded field at the point plus each
// side's offset, δn scaled by `index_scale` (dispersion) — and the
// unpolarised Fresnel reflectance (1 under total internal reflection; 0
// where the object's Fresnel reflection is off).
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

SurfaceEvent sharp_surface_event(SurfaceCrossing crossing, vec3 x, vec3 d, uint inside_mask, float index_scale) {
    uint k = uint(crossing.surface);
    vec4 shape_a = sharp_surfaces[k].shape_a;
    vec4 shape_b = sharp_surfaces[k].shape_b;
    SurfaceEvent event;
    bool mesh = EIKON_SHARP_SURFACES == 2 && crossing.triangle >= 0;
    vec3 on = mesh ? onto_triangle(crossing.triangle, x) : onto_surface(shape_a, shape_b, x);
    event.beyond_mask = inside_mask ^ (1u << k);
    event.beyond_offset = sharp_index_offset(event.beyond_mask);
    float graded = sample_gradient_and_delta(on).w;
    event.n_here = reference_index() + index_scale * (graded + sharp_index_offset(inside_mask));
    event.n_beyond = reference_index() + index_scale * (graded + event.beyond_offset);
    vec3 outward = mesh ? triangle_facet_normal(crossing.triangle) : surface_normal(shape_a, shape_b, on);
    vec3 facet_facing = dot(d, outward) < 0.0f ? outward : -outward;
    event.facing = mesh ? triangle_facing_normal(crossing.triangle, crossing.uv, d, facet_facing, event.n_here, event.n_beyond)
                        : facet_facing;
    float clearance = mesh ? triangle_surface_clearance() : 0.0f;
    event.x_reflected = on + clearance * facet_facing;
    event.x_transmitted = on - clearance * facet_facing;
    event.reflectance = fresnel_reflectance(-dot(d, event.facing), event.n_here, event.n_beyond);
    if (event.reflectance < 1.0f && sharp_surfaces[k].optics.y < 0.5f) event.reflectance = 0.0f;
    return event;
}
