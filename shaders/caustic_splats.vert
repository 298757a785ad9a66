// Draws the splats caustic_polygons.comp listed into the atlas of the
// receivers' maps (render/stages/CausticPolygons.h) as points two atlas
// texels wide: a point covers the centres of the four texels around it, and
// caustic_splats.frag gives each its bilinear share of the power. The texels
// of the four off the receiver's square (at its edge) take no share, the
// others theirs over the shares of those on it (bilinear_share_on_map), so
// no power is lost, as in common/caustic_deposits.glsl's splat_at. The atlas is drawn with its
// viewport a texel wider on every side, so that a point whose centre lies
// just past the atlas's edge still reaches the texels inside. No vertex
// buffer: gl_VertexID names the splat.
#include "common/receiver.glsl"
#include "common/receiver_blocks.glsl"
#include "common/caustic_atlas.glsl"

layout(std430, binding = kCausticSplats) readonly buffer CausticSplats { vec4 caustic_splats[]; };

uniform ivec2 atlas_size;

flat out vec2 splat_pixel;      // the splat's centre, in atlas pixels (texel centres at + 0.5)
flat out ivec3 splat_map;       // its receiver's map: first atlas row, texels per edge; z unused
flat out vec3 splat_watts;      // its power over the shares of the texels on the receiver

void main() {
    vec4 where = caustic_splats[2 * gl_VertexID];
    int r = int(round(where.z));
    int resolution = int(receivers[r].map.y);
    vec2 texel = where.xy * float(resolution);  // in the map's pixels
    float on_receiver = bilinear_share_on_map(where.xy, resolution);
    int row = atlas_row(r);
    splat_pixel = texel + vec2(0.0f, float(row));
    splat_map = ivec3(row, resolution, 0);
    splat_watts = on_receiver > 0.0f ? caustic_splats[2 * gl_VertexID + 1].rgb / on_receiver : vec3(0.0f);
    // The viewport spans the atlas and a texel beyond each edge; a splat with
    // no texel on its receiver goes past the clip volume.
    vec2 ndc = (splat_pixel + 1.0f) / vec2(atlas_size + 2) * 2.0f - 1.0f;
    gl_Position = on_receiver > 0.0f ? vec4(ndc, 0.0f, 1.0f) : vec4(2.0f, 2.0f, 0.0f, 1.0f);
    gl_PointSize = 2.0f;
}
