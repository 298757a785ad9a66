// The vertices of the image-space caustic maps (render/stages/CausticPolygons.h):
// per light texel and sheet (0: refracted through the surface, 1: reflected
// by it), the straight flight in which that texel's photon ends, the first
// receiver it lands on and the power it carries. The photon pass of
// image_space_caustics.comp writes them; caustic_polygons.comp joins
// neighbours into triangles, on every receiver one of them lands on (the
// flight, not only the landing, lets a cell whose photons land on two
// receivers, or past a receiver's edge, be drawn on each). The photon pass
// writes them to the buffer; the cell pass reads the same buffer as a
// buffer texture (render/stages/CausticPolygons.h says why). GLSL only;
// needs receiver.glsl and receiver_blocks.glsl.

#include "common/caustic_sheets.glsl"
#include "common/surface_layers.glsl"

// [3·(2·texel + sheet)]: (flight origin, surface); [+ 1]: (direction, receiver or −1);
// [+ 2]: (W rgb, the facet normals packed: an integer under 2^24, exact as a float)
layout(std430, binding = kCausticVertices) writeonly buffer CausticVertices { vec4 caustic_vertices[]; };
layout(binding = kCausticVertexTexture) uniform samplerBuffer caustic_vertex_texels;

struct CausticVertex {
    int receiver;    // the first receiver whose lit side it lands on; −1: none
    int surface;     // the sharp surface the light texel shows
    vec3 origin;     // its last straight flight: from here
    vec3 direction;  // along this (unit)
    vec3 watts;      // the power of the texel's photon on landing
    // The surface's normal where the photon met it (facing the light) and
    // where it last left it (along its flight; the first again for a
    // reflection, or for a photon that ends inside): neighbours whose
    // normals differ by more than a crease met the surface on different
    // facets of an edge (caustic_polygons.comp).
    vec3 entry_normal;
    vec3 exit_normal;
};

// A unit normal in 12 bits: its octahedral coordinates at 6 bits each, to
// a few degrees, which tells facets apart at a crease.
uint pack_facet_normal(vec3 n) {
    uvec2 q = uvec2(round((octahedral_encode(n) * 0.5f + 0.5f) * 63.0f));
    return q.x | (q.y << 6);
}

vec3 unpack_facet_normal(uint bits) {
    return octahedral_decode(vec2(uvec2(bits, bits >> 6) & 63u) / 63.0f * 2.0f - 1.0f);
}

uint caustic_vertex_slot(uint texel, int sheet) { return 3u * (uint(kCausticSheets) * texel + uint(sheet)); }

void write_caustic_vertex(uint texel, int sheet, CausticVertex v) {
    uint slot = caustic_vertex_slot(texel, sheet);
    caustic_vertices[slot] = vec4(v.origin, float(v.surface));
    caustic_vertices[slot + 1u] = vec4(v.direction, float(v.receiver));
    uint facets = pack_facet_normal(v.entry_normal) | (pack_facet_normal(v.exit_normal) << 12);
    caustic_vertices[slot + 2u] = vec4(v.watts, float(facets));
}

// The sharp surface a vertex's light texel shows (−1: none), read alone.
int caustic_vertex_surface(uint texel, int sheet) {
    return int(round(texelFetch(caustic_vertex_texels, int(caustic_vertex_slot(texel, sheet))).w));
}

CausticVertex read_caustic_vertex(uint texel, int sheet) {
    int slot = int(caustic_vertex_slot(texel, sheet));
    vec4 a = texelFetch(caustic_vertex_texels, slot), b = texelFetch(caustic_vertex_texels, slot + 1),
         c = texelFetch(caustic_vertex_texels, slot + 2);
    uint facets = uint(c.w);
    return CausticVertex(int(round(b.w)), int(round(a.w)), a.xyz, b.xyz, c.rgb, unpack_facet_normal(facets),
                         unpack_facet_normal(facets >> 12));
}

// A receiver's plane and square, read once for the flights met with it.
struct ReceiverPlane {
    vec3 origin;  // the square's centre
    vec3 normal;  // toward its lit side
    vec3 axis_u, axis_v;
    float size;   // edge, m
};

ReceiverPlane receiver_plane(int r) {
    return ReceiverPlane(receivers[r].origin.xyz, receivers[r].normal.xyz, receivers[r].axis_u.xyz,
                         receivers[r].axis_v.xyz, receivers[r].origin.w);
}

// Where a vertex's flight meets a receiver's plane from its lit side, in
// the receiver's map coordinates (outside [0, 1)² past the square's edges);
// false where the flight runs away from the plane, along it, or arrives
// from behind.
bool flight_on_plane(CausticVertex v, ReceiverPlane plane, out vec2 map_uv) {
    map_uv = vec2(0.0f);
    float approach = dot(v.direction, plane.normal);
    if (approach >= -1e-6f) return false;
    float t = dot(plane.origin - v.origin, plane.normal) / approach;
    if (t < -1e-4f * plane.size) return false;
    map_uv = receiver_map_coordinates(v.origin + t * v.direction, plane.origin, plane.axis_u, plane.axis_v, plane.size);
    return true;
}
