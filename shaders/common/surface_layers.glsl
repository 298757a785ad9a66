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

LayerSample layer_sample(sampler2D layer, ivec2 texel) {
    vec4 value = texelFetch(layer, texel, 0);
    return LayerSample(octahedral_decode(value.xy), value.z, int(value.w + 0.5f) - 1);
}

// The layer at a point between texel centres: bilinear in normal and
// distance where the four texels around it show the same surface as the
// texel holding it, else that texel's own. A texel's normal and distance
// are its centre's; read at the nearest texel, a point half a texel off
// takes a normal half a texel away on the surface, which at the back of a
// glass sphere turns its ray by pixels.
LayerSample layer_sample_between(sampler2D layer, vec2 coordinate, ivec2 size) {
    ivec2 own = clamp(ivec2(coordinate), ivec2(0), size - 1);
    LayerSample nearest = layer_sample(layer, own);
    vec2 shifted = coordinate - 0.5f;
    ivec2 base = ivec2(floor(shifted));
    if (nearest.surface < 0 || any(lessThan(base, ivec2(0))) || any(greaterThanEqual(base + 1, size))) return nearest;
    vec2 f = shifted - vec2(base);
    vec3 normal = vec3(0.0f);
    float distance = 0.0f;
    for (int corner = 0; corner < 4; ++corner) {
        ivec2 step_ = ivec2(corner & 1, corner >> 1);
        LayerSample s = layer_sample(layer, base + step_);
        if (s.surface != nearest.surface) return nearest;
        float weight = (step_.x == 1 ? f.x : 1.0f - f.x) * (step_.y == 1 ? f.y : 1.0f - f.y);
        normal += weight * (dot(s.normal, nearest.normal) < 0.0f ? -s.normal : s.normal);
        distance += weight * s.distance;
    }
    return LayerSample(normalize(normal), distance, nearest.surface);
}
