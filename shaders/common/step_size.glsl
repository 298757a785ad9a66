// Adaptive step sizes from the octree of [Sun08] (§4.2, §5.3): the
// step reaches the boundary of the octree node around the photon, clamped
// between Δs_min and the node's step cap. Shared by GLSL and C++
// (cpp_shim.h; tests/unit/test_step_size.cpp).

// Distance from x (inside the box) along the unit direction d to where it
// leaves the axis-aligned box [box_min, box_min + box_size].
float box_exit_distance(vec3 x, vec3 d, vec3 box_min, vec3 box_size) {
    vec3 far_face = box_min + mix(vec3(0.0f), box_size, greaterThan(d, vec3(0.0f)));
    vec3 t = (far_face - x) / d;
    t = mix(t, vec3(1e30f), equal(d, vec3(0.0f)));
    return max(0.0f, min(min(t.x, t.y), t.z));
}

// Step from x along d inside the octree node of `level` (edge 2^level voxels)
// that contains it: to just past the node's far face, clamped to
// [min_step, max_step].
float octree_step(vec3 x, vec3 d, vec3 grid_min, vec3 voxel_size, float level, float min_step, float max_step) {
    vec3 node_size = voxel_size * exp2(level);
    vec3 node_min = grid_min + floor((x - grid_min) / node_size) * node_size;
    float to_boundary = box_exit_distance(x, d, node_min, node_size) + 1e-3f * min(voxel_size.x, min(voxel_size.y, voxel_size.z));
    return clamp(to_boundary, min_step, max_step);
}
