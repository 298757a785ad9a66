// Sharp mesh and water surfaces: each object's triangles in a
// bounding-volume hierarchy (sim/SharpMeshSurfaces.h, refitted to the
// deforming mesh every frame; the layout is bridge/grid/FieldSet.h's). A
// surface of this kind (shape_a.w = kSharpTriangles) keeps its root node in
// shape_b.w. GLSL only: it reads storage buffers.
//
// A step's chord is intersected with the triangles by Möller–Trumbore
// (ray–triangle in barycentrics; Möller and Trumbore 1997) below a
// stack-based traversal of the tree, nearest hit first. A hit's normal is
// the triangle's corner normals interpolated (the smooth surface the facets
// stand for; the facet's own normal at creases), unless that would send the
// refracted or reflected ray to the wrong side of the facet, where the
// facet's normal is used. Inside and outside at a point come from the
// parity of the crossings of a ray to infinity (the Jordan–Brouwer theorem
// for a closed mesh), which also makes the mesh's winding irrelevant.

#include "common/loop_budget.glsl"

layout(std430, binding = kSurfaceNodes) readonly buffer SurfaceNodes { vec4 surface_nodes[]; };  // 2 per node
layout(std430, binding = kSurfaceTriangles) readonly buffer SurfaceTriangles { vec4 surface_triangles[]; };  // 6 per triangle

// Nodes pending in a traversal: one per level of a median-split tree, which
// for the 2²⁴ triangles an object may have is 23 deep.
const int EIKON_TRIANGLE_STACK = 32;
// Barycentric slack of a hit used to find the nearest crossing: a ray
// through a shared edge then meets both triangles (at the same t; one event)
// rather than slipping between them in float.
const float EIKON_TRIANGLE_SLACK = 1e-6f;

int triangle_root(vec4 shape_b) { return int(shape_b.w + 0.5f); }

// The ray x + t·d's parameter where it meets triangle i, and the barycentric
// weights (u, v) of its second and third corners; x < 0 when it misses
// (`slack`: how far outside the triangle, in barycentrics, still hits).
vec3 triangle_hit(int i, vec3 x, vec3 d, float slack) {
    vec3 a = surface_triangles[6 * i].xyz;
    vec3 e1 = surface_triangles[6 * i + 1].xyz - a;
    vec3 e2 = surface_triangles[6 * i + 2].xyz - a;
    vec3 p = cross(d, e2);
    float det = dot(e1, p);
    if (det == 0.0f) return vec3(-1.0f);  // the ray runs in the triangle's plane
    float inv = 1.0f / det;
    vec3 s = x - a;
    float u = dot(s, p) * inv;
    vec3 q = cross(s, e1);
    float v = dot(d, q) * inv;
    if (u < -slack || v < -slack || u + v > 1.0f + slack) return vec3(-1.0f);
    return vec3(dot(e2, q) * inv, u, v);
}

// What a traversal found: the nearest hit in (t_min, t_max) — t, triangle
// (−1: none), barycentrics — or, when counting, how many hits lie beyond t_min.
struct TriangleTrace {
    float t;
    int triangle;
    vec2 uv;
    int hits;
};

// The ray's parameters (t_enter, t_leave) within node n's box; t_enter >
// t_leave when it misses.
vec2 node_interval(int n, vec3 x, vec3 inv_d) {
    vec3 t1 = (surface_nodes[2 * n].xyz - x) * inv_d;
    vec3 t2 = (surface_nodes[2 * n + 1].xyz - x) * inv_d;
    vec3 near = min(t1, t2);
    vec3 far = max(t1, t2);
    return vec2(max(near.x, max(near.y, near.z)), min(far.x, min(far.y, far.z)));
}

// Depth first, the nearer child first; a pending node is dropped once a hit
// nearer than its box is found (when counting, nothing is dropped). Stops
// early, with what it found so far, when the loop budget runs out (the
// caller ends its ray then).
TriangleTrace trace_triangles(int root, vec3 x, vec3 d, float t_min, float t_max, bool count_all) {
    TriangleTrace found;
    found.t = t_max;
    found.triangle = -1;
    found.uv = vec2(0.0f);
    found.hits = 0;
    float slack = count_all ? 0.0f : EIKON_TRIANGLE_SLACK;
    vec3 inv_d = 1.0f / mix(d, vec3(1e-12f), lessThan(abs(d), vec3(1e-12f)));
    vec2 span = node_interval(root, x, inv_d);
    if (!(span.x <= span.y && span.y > t_min && span.x < found.t)) return found;
    int pending_node[EIKON_TRIANGLE_STACK];
    float pending_enter[EIKON_TRIANGLE_STACK];
    int top = 0;
    int node = root;
    for (;;) {
        int first = int(surface_nodes[2 * node].w + 0.5f);
        int count = int(surface_nodes[2 * node + 1].w + 0.5f);
        spend_loops(1u + uint(count));
        bool descend = false;
        if (count == 0) {
            vec2 a = node_interval(first, x, inv_d);
            vec2 b = node_interval(first + 1, x, inv_d);
            bool hit_a = a.x <= a.y && a.y > t_min && a.x < found.t;
            bool hit_b = b.x <= b.y && b.y > t_min && b.x < found.t;
            if (hit_a && hit_b) {
                bool a_first = a.x <= b.x;
                if (top < EIKON_TRIANGLE_STACK) {
                    pending_node[top] = a_first ? first + 1 : first;
                    pending_enter[top] = a_first ? b.x : a.x;
                    ++top;
                }
                node = a_first ? first : first + 1;
                descend = true;
            } else if (hit_a || hit_b) {
                node = hit_a ? first : first + 1;
                descend = true;
            }
        } else {
            for (int i = first; i < first + count; ++i) {
                vec3 hit = triangle_hit(i, x, d, slack);
                if (hit.x <= t_min || hit.x >= found.t) continue;
                if (count_all) {
                    ++found.hits;
                } else {
                    found.t = hit.x;
                    found.triangle = i;
                    found.uv = hit.yz;
                }
            }
        }
        if (!loops_left()) break;
        if (descend) continue;
        uint dropped = 0u;
        while (top > 0 && !(pending_enter[top - 1] < found.t)) {
            --top;
            ++dropped;
        }
        spend_loops(dropped);
        if (top == 0) break;
        node = pending_node[--top];
    }
    return found;
}

// Whether x lies inside the mesh: an odd number of crossings along a fixed
// direction that no axis, face diagonal or body diagonal of a modelled mesh
// is likely to run along.
bool inside_triangle_surface(vec4 shape_b, vec3 x) {
    const vec3 away = vec3(0.5377f, 0.6991f, 0.4712f);
    return (trace_triangles(triangle_root(shape_b), x, normalize(away), 0.0f, EIKON_NO_CROSSING, true).hits & 1) == 1;
}

// The nearest crossing along the unit d from x in (t_min, reach): t (reach
// when none), triangle (−1: none) and barycentrics.
TriangleTrace triangle_surface_crossing(vec4 shape_b, vec3 x, vec3 d, float reach, float t_min) {
    return trace_triangles(triangle_root(shape_b), x, d, t_min, reach, false);
}

// The triangle's unit normal (either orientation).
vec3 triangle_facet_normal(int i) {
    vec3 a = surface_triangles[6 * i].xyz;
    return normalize(cross(surface_triangles[6 * i + 1].xyz - a, surface_triangles[6 * i + 2].xyz - a));
}

// The corner normals at barycentrics uv (either orientation; zero when the
// corners have none, as a degenerate triangle's).
vec3 triangle_smooth_normal(int i, vec2 uv) {
    vec3 n = (1.0f - uv.x - uv.y) * surface_triangles[6 * i + 3].xyz + uv.x * surface_triangles[6 * i + 4].xyz +
             uv.y * surface_triangles[6 * i + 5].xyz;
    float length_ = length(n);
    return length_ > 0.0f ? n / length_ : vec3(0.0f);
}

// p moved along the facet's normal onto its plane (a step's end lies on the
// chord's hit up to the curvature of the path in graded media).
vec3 onto_triangle(int i, vec3 p) {
    vec3 n = triangle_facet_normal(i);
    return p - dot(p - surface_triangles[6 * i].xyz, n) * n;
}

// How far off a facet a ray goes on, on the side it continues on: far above
// the float resolution of positions (~1e-7 of the grid's size), far below
// any length the grid resolves.
float triangle_surface_clearance() { return 1e-4f * min(grid.voxel_size.x, min(grid.voxel_size.y, grid.voxel_size.z)); }

// The normal facing the ray of unit d to refract and reflect about at a hit
// of triangle i: the smooth normal, turned to the ray, unless with it the
// reflected ray would not leave the facet on the ray's side or the
// transmitted one (from n_here into n_beyond) not on the other; then the
// facet's normal `facet_facing` (which faces the ray).
vec3 triangle_facing_normal(int i, vec2 uv, vec3 d, vec3 facet_facing, float n_here, float n_beyond) {
    vec3 smooth_ = triangle_smooth_normal(i, uv);
    if (dot(smooth_, facet_facing) < 0.0f) smooth_ = -smooth_;
    float cos_i = -dot(d, smooth_);
    if (!(cos_i > 0.0f)) return facet_facing;
    if (dot(mirrored_direction(d, smooth_), facet_facing) <= 0.0f) return facet_facing;
    float eta = n_here / n_beyond;
    bool total = eta * eta * (1.0f - cos_i * cos_i) >= 1.0f;
    if (!total && dot(refracted_direction(d, smooth_, n_here, n_beyond), facet_facing) >= 0.0f) return facet_facing;
    return smooth_;
}
