// Draws the caustic triangles caustic_polygons.comp listed into the atlas of
// the receivers' maps (render/stages/CausticPolygons.h): receiver r's map
// occupies atlas rows atlas_row(r) onwards, a texel per pixel, so a triangle
// adds its W per texel to every texel whose centre it covers. Clip
// distances keep it inside its receiver's square. No vertex buffer:
// gl_VertexID names triangle and corner.
#include "common/receiver.glsl"
#include "common/receiver_blocks.glsl"
#include "common/caustic_atlas.glsl"

layout(std430, binding = kCausticTriangles) readonly buffer CausticTriangles { vec4 caustic_triangles[]; };

uniform ivec2 atlas_size;

out float gl_ClipDistance[4];
flat out vec3 texel_watts;

void main() {
    int triangle = gl_VertexID / 3, corner = gl_VertexID % 3;
    vec4 ab = caustic_triangles[3 * triangle], c = caustic_triangles[3 * triangle + 1];
    vec2 uv = corner == 0 ? ab.xy : corner == 1 ? ab.zw : c.xy;
    int r = int(round(c.z));
    float resolution = float(receivers[r].map.y);
    vec2 pixel = vec2(uv.x * resolution, float(atlas_row(r)) + uv.y * resolution);
    gl_Position = vec4(pixel / vec2(atlas_size) * 2.0f - 1.0f, 0.0f, 1.0f);
    gl_ClipDistance[0] = uv.x;
    gl_ClipDistance[1] = 1.0f - uv.x;
    gl_ClipDistance[2] = uv.y;
    gl_ClipDistance[3] = 1.0f - uv.y;
    texel_watts = caustic_triangles[3 * triangle + 2].rgb;
}
