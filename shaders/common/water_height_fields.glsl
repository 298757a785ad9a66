// The water bodies as height fields (render/stages/WaterHeightFields.h),
// for image space: where a ray crosses a water body's boundary, found on
// the node grid of its surface instead of in a viewpoint's layers. The body
// is the basin's box cut by the surface: x and z within the basin, y from
// the basin's bottom up to the surface, whose triangles are those of
// sim/deform/WaterSurface::mesh (cell (i, k) cut along its diagonal from
// node (i, k) to (i + 1, k + 1)), with the corner normals the tracers read
// (FieldSet.h), interpolated by barycentric weights as the raster pipeline
// interpolates them. Crossings are exact on those triangles: along a ray
// the height above a triangle's plane is linear, so its root is found in
// closed form. Only the slab between the lowest and the highest node is
// walked, cell by cell (2D DDA, [Amanatides87]); below it a point is in
// the water, above it outside. GLSL only.

struct WaterBody { EIKON_GPU_WATER_HEIGHT_FIELD };
layout(std140, binding = kWaterBodies) uniform WaterBodies { WaterBody water_bodies[kMaxSharpObjects]; };
// Per body: a texel (lowest node y, highest node y, the steepest slope
// |∇y| of a surface triangle, 0), then per node, x fastest, (corner normal, y).
layout(binding = kWaterNodeTexture) uniform samplerBuffer water_node_texels;

struct WaterCrossing {
    bool found;
    float t;      // along the ray
    vec3 normal;  // outward: out of the water
};

vec4 water_node(WaterBody body, int i, int k) { return texelFetch(water_node_texels, body.grid.z + k * body.grid.x + i); }

vec2 water_spacing(WaterBody body) { return (body.high.xz - body.low.xz) / vec2(body.grid.xy - 1); }

// Cell (i, k)'s surface, cut along its diagonal from node (i, k) to
// (i + 1, k + 1): its corners' heights, and the rise per cell along (u, v)
// of its two triangles. Over the triangle v ≥ u the surface rises h00 +
// u·(h11 − h01) + v·(h01 − h00), over u ≥ v h00 + u·(h10 − h00) + v·(h11 −
// h10).
struct WaterCell {
    vec4 heights;      // h00, h10, h01, h11
    vec2 upper_slope;  // the triangle v ≥ u
    vec2 lower_slope;  // the triangle u ≥ v
};

WaterCell water_cell(WaterBody body, ivec2 cell) {
    float h00 = water_node(body, cell.x, cell.y).w, h11 = water_node(body, cell.x + 1, cell.y + 1).w;
    float h01 = water_node(body, cell.x, cell.y + 1).w, h10 = water_node(body, cell.x + 1, cell.y).w;
    return WaterCell(vec4(h00, h10, h01, h11), vec2(h11 - h01, h01 - h00), vec2(h10 - h00, h11 - h10));
}

// Barycentric weights of cell-local (u, v) ∈ [0, 1]² for the corners
// (0,0), the side corner, (1,1): the triangle v ≥ u has side corner (0,1),
// the triangle u ≥ v has (1,0).
vec3 water_weights(vec2 uv, bool upper) {
    return upper ? vec3(1.0f - uv.y, uv.y - uv.x, uv.x) : vec3(1.0f - uv.x, uv.x - uv.y, uv.y);
}

// The first crossing of the water body's boundary by x + t·d for t in
// (t_from, t_to]; t_from must lie off the boundary by more than rounding.
// leaving_only: only where the ray leaves the water (a ray followed inside
// from where a layer put its entry, which may lie a rounding above the
// triangles: it enters them again first).
// No return or branch skips work: a CPU rasterizer runs every path of a
// SIMD group under a mask, so each event is a select, and the walk's loop
// ends when its lanes have all found theirs.
WaterCrossing water_crossing(int body_index, vec3 x, vec3 d, float t_from, float t_to, bool leaving_only) {
    WaterBody body = water_bodies[body_index];
    vec3 slab = texelFetch(water_node_texels, body.grid.z - 1).xyz;  // the lowest and the highest node's y, the steepest slope
    // Widened by a hair (10 ppm of the basin's depth), so that still water,
    // whose slab is a plane, is walked across too.
    float hair = 1e-5f * (body.high.y - body.low.y) + 1e-7f;
    slab.xy += vec2(-hair, hair);
    // The box that holds the water: the basin up to the highest node.
    vec3 low = body.low.xyz, high = vec3(body.high.x, max(slab.y, body.low.y), body.high.z);
    vec3 inverse = 1.0f / vec3(abs(d.x) > 1e-20f ? d.x : 1e-20f, abs(d.y) > 1e-20f ? d.y : 1e-20f,
                               abs(d.z) > 1e-20f ? d.z : 1e-20f);
    vec3 ta = (low - x) * inverse, tb = (high - x) * inverse;
    vec3 near_ = min(ta, tb), far_ = max(ta, tb);
    float box_in = max(max(near_.x, near_.y), near_.z), box_out = min(min(far_.x, far_.y), far_.z);
    bool crosses_box = box_out >= box_in && box_out > t_from && box_in <= t_to;
    vec3 in_axis = near_.x == box_in ? vec3(1, 0, 0) : near_.y == box_in ? vec3(0, 1, 0) : vec3(0, 0, 1);
    vec3 out_axis = far_.x == box_out ? vec3(1, 0, 0) : far_.y == box_out ? vec3(0, 1, 0) : vec3(0, 0, 1);
    // Whether the ray enters the box below the surface (through a wall or
    // the bottom), and leaves it so: certainly where that point lies below
    // the slab; within the slab the walk below tells.
    bool enters = crosses_box && !leaving_only && box_in > t_from;
    bool leaves = crosses_box && box_out <= t_to;
    WaterCrossing crossing = WaterCrossing(enters && x.y + box_in * d.y < slab.x, box_in, -sign(d) * in_axis);
    // The surface's crossings, in the slab where y lies between the lowest and the highest node.
    float slab_a = (slab.x - x.y) * inverse.y, slab_b = (slab.y - x.y) * inverse.y;
    float from = max(max(t_from, box_in), min(slab_a, slab_b));
    float to = min(min(t_to, box_out), max(slab_a, slab_b));
    vec2 spacing = water_spacing(body);
    vec2 g = (x.xz + from * d.xz - body.low.xz) / spacing;  // grid coordinates where the walk starts
    vec2 dg = d.xz / spacing;
    ivec2 cell = clamp(ivec2(floor(g)), ivec2(0), body.grid.xy - 2);
    ivec2 step_ = ivec2(dg.x >= 0.0f ? 1 : -1, dg.y >= 0.0f ? 1 : -1);
    vec2 inverse_g = 1.0f / vec2(abs(dg.x) > 1e-20f ? dg.x : 1e-20f, abs(dg.y) > 1e-20f ? dg.y : 1e-20f);
    float t = from;
    // A ray from within the water that descends more steeply than any
    // triangle rises stays under the surface (y(t) ≤ y(0) + d.y·t < H(x0) −
    // slope·|d.xz|·t ≤ H at the point below it): only the box's walls and
    // bottom are left to cross.
    bool stays_under = leaving_only && -d.y > slab.z * length(d.xz) * 1.0001f;
    bool walking = crosses_box && !crossing.found && from < to && !stays_under;
    bool on_surface = false;  // the crossing found is the surface's: its normal is taken after the walk
    // The ray's height above the surface where the walk has got to, as the
    // last part reckoned it: the next part takes its side from there, so a
    // crossing on a cell's edge, where two planes' roundings disagree on
    // the side, is found once.
    float end_height = 1.0f;
    bool started = false;
    ivec2 hit_cell = cell;
    bool hit_upper = false;
    for (int c = 0; walking && c < body.grid.x + body.grid.y; ++c) {
        // Where the ray leaves this cell, and where it crosses its diagonal u = v.
        vec2 leave = (vec2(cell + max(step_, ivec2(0))) - g) * inverse_g + from;
        float cell_end = min(min(leave.x, leave.y), to);
        vec2 origin = g - vec2(cell) - from * dg;  // (u, v) at t = 0
        float diagonal = abs(dg.x - dg.y) > 1e-20f ? (origin.y - origin.x) / (dg.x - dg.y) : -1.0f;
        float split = diagonal > t && diagonal < cell_end ? diagonal : cell_end;
        // The ray's height above the cell's triangles is linear in t over
        // each part of the ray across the cell.
        WaterCell surface_here = water_cell(body, cell);
        float h00 = surface_here.heights.x;
        vec2 upper_slope = surface_here.upper_slope, lower_slope = surface_here.lower_slope;
        float ends[3] = float[3](t, split, cell_end);
        for (int part = 0; part < 2; ++part) {
            float a = ends[part], b = ends[part + 1];
            vec2 middle = origin + 0.5f * (a + b) * dg;
            bool upper = middle.y >= middle.x;
            vec2 slope = upper ? upper_slope : lower_slope;
            float above = x.y - h00 - dot(origin, slope), rate = d.y - dot(dg, slope);
            float ha = above + rate * a, hb = above + rate * b;
            bool open = !crossing.found && b > a;
            // Entering the box below the surface, where the walk starts there.
            bool wall_in = open && enters && a == box_in && ha < 0.0f;
            bool above_at_a = started ? end_height > 0.0f : ha > 0.0f;
            bool surface = open && !wall_in && above_at_a != (hb > 0.0f) && (!leaving_only || hb > 0.0f);
            float root = ha != hb ? clamp(a + (b - a) * ha / (ha - hb), a, b) : a;
            crossing.t = surface ? root : wall_in ? box_in : crossing.t;
            crossing.normal = wall_in ? -sign(d) * in_axis : crossing.normal;
            crossing.found = crossing.found || surface || wall_in;
            end_height = open ? hb : end_height;
            started = started || open;
            on_surface = on_surface || surface;
            hit_cell = surface ? cell : hit_cell;
            hit_upper = surface ? upper : hit_upper;
        }
        t = cell_end;
        if (leave.x <= leave.y) cell.x += step_.x;
        else cell.y += step_.y;
        walking = !crossing.found && cell_end < to && all(greaterThanEqual(cell, ivec2(0))) &&
                  all(lessThanEqual(cell, body.grid.xy - 2));
    }
    // The surface's normal at the crossing: its corners' normals, weighted as the raster pipeline weighs them.
    vec2 uv = clamp(g - vec2(hit_cell) + (crossing.t - from) * dg, 0.0f, 1.0f);
    vec3 w = water_weights(uv, hit_upper);
    vec3 normal = normalize(w.x * water_node(body, hit_cell.x, hit_cell.y).xyz +
                            w.y * water_node(body, hit_cell.x + (hit_upper ? 0 : 1), hit_cell.y + (hit_upper ? 1 : 0)).xyz +
                            w.z * water_node(body, hit_cell.x + 1, hit_cell.y + 1).xyz);
    crossing.normal = on_surface ? (normal.y < 0.0f ? -normal : normal) : crossing.normal;
    // Leaving the box under the surface: where the walk ends on a wall (off
    // the grid, or at the box's end), below the slab, or all the way under
    // the surface; through a wall or the bottom.
    bool off_grid = any(lessThan(cell, ivec2(0))) || any(greaterThan(cell, body.grid.xy - 2));
    bool walked_out = end_height < 0.0f && (off_grid || t >= box_out);
    bool deep_out = !crossing.found && leaves && (walked_out || x.y + box_out * d.y < slab.x || stays_under);
    crossing = deep_out ? WaterCrossing(true, box_out, sign(d) * out_axis) : crossing;
    crossing.t = crossing.found ? crossing.t : t_to;
    return crossing;
}
