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

// A camera ray's step of `reach` = step_voxels × the voxel's edges along
// each axis, for voxels that are boxes: the longest s over which the ray
// moves at most reach_i along every axis i, its bend counted four times.
// The path bends by the curvature vector `bend` = (∇n − (∇n·d)·d)/n (the
// ray equation, d(n·d)/ds = ∇n): along axis i it moves |d_i|·s +
// ½|bend_i|·s²; the step keeps |d_i|·s + 2·|bend_i|·s² ≤ reach_i, so
// s_i = 2·reach_i / (|d_i| + √(d_i² + 8·|bend_i|·reach_i)). Where the ray
// levels off, the leapfrog's energy error grows as s² times the field's
// curvature across the ray (about |bend|/edge where the field varies on the
// scale of a voxel): counted once, the bend let
// the level rays of scenes/hot_road_mirage.json take 13 m steps at its
// mirage's turning points, and the turned rays left 4.6% off the angle they
// came down at (tests/integration/test_mirage.cpp), 0.09% counted four
// times. The step is clamped to [shortest, longest], step_voxels times the
// smallest and the largest edge: on cubic voxels it is step_voxels edges
// whatever the direction, as an isotropic step; on flat voxels a nearly
// level ray takes the step that crosses step_voxels of the thin layers,
// not step_voxels of their thickness along its path.
float voxel_crossing_step(vec3 d, vec3 bend, vec3 reach, float shortest, float longest) {
    if (longest <= shortest) return shortest;  // cubic voxels: nothing to weigh
    vec3 along = abs(d);
    vec3 per_axis = 2.0f * reach / max(along + sqrt(along * along + 8.0f * abs(bend) * reach), vec3(1e-30f));
    return clamp(min(per_axis.x, min(per_axis.y, per_axis.z)), shortest, longest);
}
