// The field grid's box as the tracers see it: where a point lies in it and
// where a straight ray crosses it. Shared by GLSL and C++: the includer
// declares `grid` (GLSL: the GridBlock uniform of common/grid_sampling.glsl;
// C++: render/stages/NativePhotonTrace.cpp) with the members of
// layout::GpuGrid under their GLSL names.

const float EIKON_INFINITY = 1e30f;

float reference_index() { return grid.bounds_min.w; }

vec3 grid_uvw(vec3 x) {
    return (x - xyz_of(grid.bounds_min)) / (xyz_of(grid.bounds_max) - xyz_of(grid.bounds_min));
}

bool grid_contains(vec3 x) {
    return all(greaterThanEqual(x, xyz_of(grid.bounds_min))) && all(lessThanEqual(x, xyz_of(grid.bounds_max)));
}

ivec3 grid_cell(vec3 x) {
    return clamp(ivec3(floor((x - xyz_of(grid.bounds_min)) / xyz_of(grid.voxel_size))), ivec3(0), ivec3(grid.resolution) - 1);
}

int grid_linear_index(ivec3 cell) {
    return cell.x + grid.resolution.x * (cell.y + grid.resolution.y * cell.z);
}

// Parameters (t_enter, t_exit) of the straight ray x + t·d inside the grid
// box (slab method); t_enter > t_exit when it misses.
vec2 grid_ray_interval(vec3 x, vec3 d) {
    vec3 inverse = 1.0f / d;
    vec3 t0 = (xyz_of(grid.bounds_min) - x) * inverse;
    vec3 t1 = (xyz_of(grid.bounds_max) - x) * inverse;
    vec3 near = min(t0, t1);
    vec3 far = max(t0, t1);
    return vec2(max(max(near.x, near.y), near.z), min(min(far.x, far.y), far.z));
}

// Of `travelled`, the length a step of length ds from `start` to x counts,
// the part inside the grid: a step that leaves the grid overshoots its
// boundary, and outside the grid nothing absorbs.
float travelled_inside_grid(vec3 start, vec3 x, float ds, float travelled) {
    if (grid_contains(x)) return travelled;
    vec3 chord = x - start;
    float chord_length = length(chord);
    if (chord_length > 0.0f)
        travelled = min(travelled, max(grid_ray_interval(start, chord / chord_length).y, 0.0f) / chord_length * ds);
    return travelled;
}
