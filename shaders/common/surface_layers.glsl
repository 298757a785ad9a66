// Surface layers (render/stages/SurfaceLayers.h): what a viewpoint — the
// camera, or a light — sees of the sharp surfaces, rasterized into two
// textures by depth peeling: the nearest surfaces, and the next surfaces
// behind them. A texel holds the surface normal (octahedral, two floats:
// exact to float rounding), the distance from the viewpoint (perspective:
// from the eye; orthographic: along the axis) and the surface's number + 1
// (0: none). The normal's sign is whatever the mesh gives; passes orient
// it against their ray. GLSL only.

struct Viewpoint {
    mat4 view_projection;
    vec3 eye;           // perspective: the eye; orthographic: a point on the near plane
    vec3 axis;          // orthographic: the direction of view
    bool orthographic;
    ivec2 size;         // texels
};

vec2 octahedral_encode(vec3 n) {
    n /= abs(n.x) + abs(n.y) + abs(n.z);
    vec2 folded = (1.0f - abs(n.yx)) * vec2(n.x >= 0.0f ? 1.0f : -1.0f, n.y >= 0.0f ? 1.0f : -1.0f);
    return n.z >= 0.0f ? n.xy : folded;
}

vec3 octahedral_decode(vec2 e) {
    vec3 n = vec3(e, 1.0f - abs(e.x) - abs(e.y));
    if (n.z < 0.0f) n.xy = (1.0f - abs(n.yx)) * vec2(n.x >= 0.0f ? 1.0f : -1.0f, n.y >= 0.0f ? 1.0f : -1.0f);
    return normalize(n);
}

float viewpoint_distance(Viewpoint view, vec3 x) {
    return view.orthographic ? dot(x - view.eye, view.axis) : length(x - view.eye);
}

// Where x projects onto the layers, in texels (texel (i, j) covers
// [i, i + 1) × [j, j + 1)), and whether it projects into them at all.
bool viewpoint_coordinate(Viewpoint view, vec3 x, out vec2 coordinate) {
    vec4 clip = view.view_projection * vec4(x, 1.0f);
    coordinate = vec2(0.0f);
    if (clip.w <= 0.0f) return false;
    vec2 ndc = clip.xy / clip.w;
    if (any(greaterThanEqual(abs(ndc), vec2(1.0f)))) return false;
    coordinate = (ndc * 0.5f + 0.5f) * vec2(view.size);
    return true;
}

// The texel of the layers that holds x, and whether x projects into them at all.
bool viewpoint_texel(Viewpoint view, vec3 x, out ivec2 texel) {
    vec2 coordinate;
    bool inside = viewpoint_coordinate(view, x, coordinate);
    texel = min(ivec2(coordinate), view.size - 1);
    return inside;
}

struct LayerSample {
    vec3 normal;
    float distance;
    int surface;  // -1: none
};

LayerSample layer_value(vec4 value) {
    return LayerSample(octahedral_decode(value.xy), value.z, int(value.w + 0.5f) - 1);
}

LayerSample layer_sample(sampler2D layer, ivec2 texel) { return layer_value(texelFetch(layer, texel, 0)); }
