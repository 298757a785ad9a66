// The vertices of the image-space caustic maps (render/stages/CausticPolygons.h):
// per light texel and sheet (0: refracted through the surface, 1: reflected
// by it), where that texel's photon lands and the power it carries. The
// photon pass of image_space_caustics.comp writes them; caustic_polygons.comp
// joins neighbours into triangles. GLSL only.

layout(std430, binding = kCausticVertices) buffer CausticVertices {
    vec4 caustic_vertices[];  // [2·(2·texel + sheet)]: (map uv, receiver or −1, surface); [+ 1]: (W rgb, 0)
};

const int kCausticSheets = 2;

struct CausticVertex {
    int receiver;  // −1: lands on no receiver's lit side
    int surface;   // the sharp surface the light texel shows
    vec2 map_uv;
    vec3 watts;    // the power of the texel's photon on landing
};

uint caustic_vertex_slot(uint texel, int sheet) { return 2u * (uint(kCausticSheets) * texel + uint(sheet)); }

void write_caustic_vertex(uint texel, int sheet, CausticVertex v) {
    uint slot = caustic_vertex_slot(texel, sheet);
    caustic_vertices[slot] = vec4(v.map_uv, float(v.receiver), float(v.surface));
    caustic_vertices[slot + 1u] = vec4(v.watts, 0.0f);
}

CausticVertex read_caustic_vertex(uint texel, int sheet) {
    uint slot = caustic_vertex_slot(texel, sheet);
    vec4 a = caustic_vertices[slot], b = caustic_vertices[slot + 1u];
    return CausticVertex(int(round(a.z)), int(round(a.w)), a.xy, b.rgb);
}
