// The water surface's triangles for the tracers, made on the GPU from its
// heights (sim/gpu/GpuWaterBody.h): what sim/SharpMeshSurfaces.cpp writes
// on the host, in FieldSet's layout (bridge/grid/FieldSet.h), for the water
// body of sim/deform/WaterSurface::mesh.
//   EIKON_PASS 0, per triangle of the mesh: its unit normal and its angles
//     at its corners, in float64 as on the host;
//   EIKON_PASS 1, per triangle in the tree's leaf order: its corners and at
//     each the normal of the smooth surface — the angle-weighted mean of
//     the normals of the corner's triangles within kCreaseCosine of this
//     one's, each turned to this one's side first (Thürmer and Wüthrich 1998);
//   EIKON_PASS 2, per node of one depth of the tree, deepest first: its box
//     — a leaf's around its triangles' corners as written (float32, and
//     float rounding keeps the order of the host's float64 minima), an
//     interior node's around its two children's.
layout(local_size_x = 256) in;

#include "sim/entry_index.glsl"

layout(std430, binding = kWaterHeight) readonly buffer WaterHeight { double height[]; };
layout(std430, binding = kWaterVertices) readonly buffer WaterVertices { dvec4 vertices[]; };
layout(std430, binding = kWaterTriangles) readonly buffer WaterTriangles { ivec4 triangles[]; };

// A vertex of the water body: a node of the surface rises with its height.
dvec3 vertex_position(int v) {
    dvec4 rest = vertices[v];
    int node = int(rest.w);
    return node >= 0 ? dvec3(rest.x, rest.y + height[node], rest.z) : rest.xyz;
}

#if EIKON_PASS == 0
layout(std430, binding = kWaterFaceNormals) writeonly buffer WaterFaceNormals { dvec4 face_normal[]; };
layout(std430, binding = kWaterFaceAngles) writeonly buffer WaterFaceAngles { dvec4 face_angles[]; };

uniform int triangle_count;

// sin t and cos t for |t| ≤ π/2 by their Taylor series, to float64 rounding.
double sine_near_zero(double t) {
    precise double term = t, sum = t;
    for (int n = 1; n <= 11; ++n) {
        term *= -t * t / double((2 * n) * (2 * n + 1));
        sum += term;
    }
    return sum;
}

double cosine_near_zero(double t) {
    precise double term = 1.0lf, sum = 1.0lf;
    for (int n = 1; n <= 11; ++n) {
        term *= -t * t / double((2 * n - 1) * (2 * n));
        sum += term;
    }
    return sum;
}

// acos in float64, which GLSL lacks: float32's acos, then Newton steps on
// cos θ = x (θ += (cos θ − x) / sin θ), cos and sin taken about π/2, until
// the step no longer changes θ; within a few ulps of the host's std::acos.
double precise_acos(double x) {
    const double kHalfPi = 1.5707963267948966lf;
    precise double theta = double(acos(float(x)));
    for (int i = 0; i < 4; ++i) {
        precise double t = theta - kHalfPi;
        precise double sine = cosine_near_zero(t);
        if (sine < 1e-6lf) break;  // θ at 0 or π: float32's answer stands
        precise double next = theta + (-sine_near_zero(t) - x) / sine;
        if (next == theta) break;
        theta = next;
    }
    return theta;
}

void main() {
    uint t = entryIndex();
    if (t >= uint(triangle_count)) return;
    ivec4 corners = triangles[t];
    dvec3 p[3] = dvec3[3](vertex_position(corners.x), vertex_position(corners.y), vertex_position(corners.z));
    precise dvec3 n = cross(p[1] - p[0], p[2] - p[0]);
    precise double length_ = sqrt(dot(n, n));
    face_normal[t] = dvec4(length_ > 0.0lf ? n / length_ : dvec3(0.0lf), 0.0lf);
    dvec4 angles = dvec4(0.0lf);
    for (int c = 0; c < 3; ++c) {
        precise dvec3 a = p[(c + 1) % 3] - p[c], b = p[(c + 2) % 3] - p[c];
        precise double la = sqrt(dot(a, a)), lb = sqrt(dot(b, b));
        if (la > 0.0lf && lb > 0.0lf) angles[c] = precise_acos(clamp(dot(a, b) / (la * lb), -1.0lf, 1.0lf));
    }
    face_angles[t] = angles;
}
#elif EIKON_PASS == 1
layout(std430, binding = kWaterSlots) readonly buffer WaterSlots { int triangle_of_slot[]; };
layout(std430, binding = kWaterCornerStart) readonly buffer WaterCornerStart { int corner_start[]; };
layout(std430, binding = kWaterCorners) readonly buffer WaterCorners { int corner_triangles[]; };
layout(std430, binding = kWaterFaceNormals) readonly buffer WaterFaceNormals { dvec4 face_normal[]; };
layout(std430, binding = kWaterFaceAngles) readonly buffer WaterFaceAngles { dvec4 face_angles[]; };
layout(std430, binding = kWaterSurfaceTriangles) writeonly buffer WaterSurfaceTriangles { vec4 surface_triangles[]; };

uniform int triangle_count;
uniform int root_node;       // the first corner's w: the mesh's root node, its ordinal
uniform double crease_cosine;

// The angle of triangle t at its corner on vertex v.
double angle_at(int t, int v) {
    ivec4 corners = triangles[t];
    dvec4 angles = face_angles[t];
    return corners.x == v ? angles.x : corners.y == v ? angles.y : angles.z;
}

void main() {
    uint slot = entryIndex();
    if (slot >= uint(triangle_count)) return;
    int t = triangle_of_slot[slot];
    ivec4 corners = triangles[t];
    dvec3 own = face_normal[t].xyz;
    for (int corner = 0; corner < 3; ++corner) {
        int v = corners[corner];
        surface_triangles[6u * slot + uint(corner)] =
            vec4(vec3(vertex_position(v)), corner == 0 ? float(root_node) : 0.0f);
        precise dvec3 sum = dvec3(0.0lf);
        for (int i = corner_start[v]; i < corner_start[v + 1]; ++i) {
            int neighbour = corner_triangles[i];
            dvec3 other = face_normal[neighbour].xyz;
            if (dot(own, other) < 0.0lf) other = -other;
            if (dot(own, other) >= crease_cosine) sum += angle_at(neighbour, v) * other;
        }
        precise double length_ = sqrt(dot(sum, sum));
        surface_triangles[6u * slot + 3u + uint(corner)] = vec4(vec3(length_ > 0.0lf ? sum / length_ : dvec3(0.0lf)), 0.0f);
    }
}
#else
layout(std430, binding = kWaterNodes) readonly buffer WaterNodes { ivec4 tree_nodes[]; };
layout(std430, binding = kWaterLevelNodes) readonly buffer WaterLevelNodes { int level_nodes[]; };
layout(std430, binding = kWaterSurfaceTriangles) readonly buffer WaterSurfaceTriangles { vec4 surface_triangles[]; };
layout(std430, binding = kWaterSurfaceNodes) buffer WaterSurfaceNodes { vec4 surface_nodes[]; };

uniform int level_first;  // this depth's nodes: level_nodes[level_first .. level_first + level_count)
uniform int level_count;

void main() {
    uint entry = entryIndex();
    if (entry >= uint(level_count)) return;
    // (slot in FieldSet's nodes, triangles in a leaf, then a leaf's first
    // triangle slot or an interior node's two children's slots)
    ivec4 node = tree_nodes[level_nodes[level_first + int(entry)]];
    vec3 low = vec3(3.0e38f), high = vec3(-3.0e38f);
    if (node.y > 0) {
        for (int slot = node.z; slot < node.z + node.y; ++slot)
            for (int corner = 0; corner < 3; ++corner) {
                vec3 x = surface_triangles[6 * slot + corner].xyz;
                low = min(low, x);
                high = max(high, x);
            }
    } else {
        low = min(surface_nodes[2 * node.z].xyz, surface_nodes[2 * node.w].xyz);
        high = max(surface_nodes[2 * node.z + 1].xyz, surface_nodes[2 * node.w + 1].xyz);
    }
    surface_nodes[2 * node.x].xyz = low;
    surface_nodes[2 * node.x + 1].xyz = high;
}
#endif
