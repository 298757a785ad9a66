// The march of a light ray through the field grid: the field (∇n, n) of
// the ray's channel with the offset of the sharp objects it is inside, the
// step policy and the integrator. Shared by GLSL and C++: the includer
// declares the march's uniforms and the ray's state (GLSL:
// common/ray_march.glsl; C++: render/stages/NativePhotonTrace.cpp),
// sample_gradient_and_delta and, with octree steps, step_node; needs
// common/grid_box.glsl and common/integrators.glsl.

// (∇n, n) for this ray's channel; used by the integrators.
vec4 field_at(vec3 x) {
    vec4 sample_ = sample_gradient_and_delta(x);
    return vec4(channel_scale * xyz_of(sample_), reference_index() + channel_scale * (sample_.w + sharp_offset));
}

float next_step(vec3 x, vec3 v) {
#if EIKON_OCTREE_STEPS
    vec2 node = step_node(grid_cell(x));
    return octree_step(x, normalize(v), xyz_of(grid.bounds_min), xyz_of(grid.voxel_size), node.x, step_length, node.y);
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
// The ray's sharp surfaces at x, when it enters the grid or starts there.
void enter_sharp_region(vec3 x) {
    inside_mask = inside_mask_at(x);
    sharp_offset = sharp_index_offset(inside_mask);
}
#endif
