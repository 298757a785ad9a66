// Draws sharp-surface triangles pulled from a buffer in the layout of
// FieldSet's surface triangles (three corners, three corner normals; the
// first corner's w the triangle's ordinal), for the surface layers of a
// viewpoint (common/surface_layers.glsl). No vertex buffer: gl_VertexID
// names triangle and corner. The buffer is read as a buffer texture: a CPU
// rasterizer shades vertices on one thread, and fetches texels for a SIMD
// group's vertices at once where it loads a storage buffer a lane and a
// float at a time (1.5 ms of the light's two peels of pool_caustics' 40 000
// triangles, 3 of the camera's, on two cores).
layout(binding = kSurfaceTriangleTexture) uniform samplerBuffer surface_triangle_texels;

uniform mat4 view_projection;
uniform int surface_of_ordinal[kMaxSharpObjects];  // the ordinal in w → the sharp surface's number

out vec3 world_position;
out vec3 corner_normal;
flat out int surface;

void main() {
    int triangle = gl_VertexID / 3, corner = gl_VertexID % 3;
    vec3 x = texelFetch(surface_triangle_texels, 6 * triangle + corner).xyz;
    world_position = x;
    corner_normal = texelFetch(surface_triangle_texels, 6 * triangle + 3 + corner).xyz;
    surface = surface_of_ordinal[int(texelFetch(surface_triangle_texels, 6 * triangle).w + 0.5f)];
    gl_Position = view_projection * vec4(x, 1.0f);
}
