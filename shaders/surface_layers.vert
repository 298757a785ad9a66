// Draws sharp-surface triangles pulled from a storage buffer in the layout
// of FieldSet's surface triangles (three corners, three corner normals; the
// first corner's w the triangle's ordinal), for the surface layers of a
// viewpoint (common/surface_layers.glsl). No vertex buffer: gl_VertexID
// names triangle and corner.
layout(std430, binding = kSurfaceTriangles) readonly buffer SurfaceTriangles { vec4 surface_triangles[]; };

uniform mat4 view_projection;
uniform int surface_of_ordinal[kMaxSharpObjects];  // the ordinal in w → the sharp surface's number

out vec3 world_position;
out vec3 corner_normal;
flat out int surface;

void main() {
    int triangle = gl_VertexID / 3, corner = gl_VertexID % 3;
    vec3 x = surface_triangles[6 * triangle + corner].xyz;
    world_position = x;
    corner_normal = surface_triangles[6 * triangle + 3 + corner].xyz;
    surface = surface_of_ordinal[int(surface_triangles[6 * triangle].w + 0.5f)];
    gl_Position = view_projection * vec4(x, 1.0f);
}
