// Two-interface refraction in image space ([Hu07] §2.1, after [Wyman05]): a
// ray that entered a sharp surface is followed to where it leaves by
// searching the viewpoint's surface layers (common/surface_layers.glsl)
// instead of the geometry. A point is inside the surface it entered while
// its texel shows that surface nearest and the point lies between the near
// layer's distance and the far layer's. The ray marches in kLayerMarchSteps
// steps across the surface's extent until a point is outside, bisects that
// step kLayerBisections times ([Hu07] Fig. 7 bisects in the depth buffer),
// and then meets the layer's tangent plane there twice (the iterative
// lookup of [Hu07] §2.1.3), taking that layer's normal; the planes are read
// bilinearly between texel centres (common/surface_layers.glsl), which puts
// the exit within a pixel where the nearest texel's plane missed by several. It refracts out by
// Snell's law with the Fresnel transmittance; a totally reflected ray is
// followed inside again, up to kInternalBounces times. Inside, a receiver it
// meets ends it (the pool floor under water), and the object's extinction
// weighs it by Beer–Lambert along the chord. The partial reflection inside
// is not followed (its power is lost), and a ray meets no second refractor
// after it leaves. A water body is the exception: its exit is found on its
// height field (common/water_height_fields.glsl), exactly on its triangles.
// Program options: EIKON_WATER_BODIES (how many the scene has),
// EIKON_LAYER_SURFACES (1: it has other sharp surfaces; a CPU rasterizer
// runs both searches under a mask where both are compiled in) and
// EIKON_SHARP_SURFACES (how many in all).
// GLSL only; needs grid_sampling.glsl (none of its textures), fresnel.glsl,
// receiver.glsl, receiver_blocks.glsl.
#ifndef EIKON_WATER_BODIES
#define EIKON_WATER_BODIES 0
#endif
#ifndef EIKON_LAYER_SURFACES
#define EIKON_LAYER_SURFACES 1
#endif
#ifndef EIKON_SHARP_SURFACES
#define EIKON_SHARP_SURFACES kMaxSharpObjects
#endif
#include "common/surface_layers.glsl"
#include "common/sharp_surface_list.glsl"
#if EIKON_WATER_BODIES > 0
#include "common/water_height_fields.glsl"
#endif

// The meshes' trees (bridge/grid/FieldSet.h), two texels per node, read as a
// buffer texture: a CPU rasterizer gathers a texel for all lanes at once
// where it loads a storage buffer a lane and a float at a time.
layout(binding = kSurfaceNodeTexture) uniform samplerBuffer surface_node_texels;
// Per sharp surface: κ rgb inside it; w its water body, or −1.
layout(std140, binding = kImageSpaceSurfaces) uniform ImageSpaceSurfaces { vec4 surface_extinction[kMaxSharpObjects]; };
layout(binding = kNearLayerTexture) uniform sampler2D near_layer;
layout(binding = kFarLayerTexture) uniform sampler2D far_layer;

const int kLayerMarchSteps = 8;
const int kLayerBisections = 10;
const int kTangentPlaneSteps = 2;
const int kInternalBounces = 2;

// Surface s's place in the blocks as a lane-varying index reads it: the
// constant 0 where the scene has one sharp surface, so that its fields are
// loaded once for all lanes (as receiver_slot, common/receiver_blocks.glsl).
int surface_slot(int s) { return EIKON_SHARP_SURFACES == 1 ? 0 : s; }

float surface_index(int s) { return reference_index() + sharp_surfaces[surface_slot(s)].optics.x; }
bool surface_reflects(int s) { return sharp_surfaces[surface_slot(s)].optics.y > 0.5f; }

// How far off a surface a ray leaving it starts, so that it does not meet
// that surface again at once: a thousandth of a voxel (1.25e-5 m in the
// default scene), a length of the scene's own scale.
float surface_offset() { return 1e-3f * min(grid.voxel_size.x, min(grid.voxel_size.y, grid.voxel_size.z)); }

// The longest chord of surface s: a sphere's diameter, a box's or a mesh's
// root box's diagonal.
float surface_reach(int s) {
    SharpSurface shape = sharp_surfaces[surface_slot(s)];
    int kind = int(shape.shape_a.w + 0.5f);
    if (kind == kSharpSphere) return 2.0f * shape.shape_b.x;
    if (kind == kSharpBox) return length(shape.shape_b.xyz - shape.shape_a.xyz);
    int root = int(shape.shape_b.w + 0.5f);
    return length(texelFetch(surface_node_texels, 2 * root + 1).xyz - texelFetch(surface_node_texels, 2 * root).xyz);
}

bool inside_layers(Viewpoint view, vec3 x, int s) {
    ivec2 texel;
    if (!viewpoint_texel(view, x, texel)) return false;
    LayerSample near_ = layer_sample(near_layer, texel);
    if (near_.surface != s) return false;
    LayerSample far_ = layer_sample(far_layer, texel);
    float d = viewpoint_distance(view, x);
    return d >= near_.distance && (far_.surface < 0 || d <= far_.distance);
}

// The point of the layer nearest in distance to x, on x's line of sight, and its normal.
// The layer (near or far) is the one whose surface at the texel holding x
// lies nearer in distance to x. It is read between texel centres: bilinear
// in normal and distance where the four texels around x show the same
// surface as the texel holding it, else that texel's own. A texel's normal
// and distance are its centre's; read at the nearest texel, a point half a
// texel off takes a normal half a texel away on the surface, which at the
// back of a glass sphere turns its ray by pixels. The texel holding x is
// one of the four around it, so each layer is read at four texels, and only
// the chosen layer's are decoded (a CPU rasterizer pays for every fetch and
// decode of every lane).
bool nearest_layer_point(Viewpoint view, vec3 x, out vec3 point, out vec3 normal) {
    vec2 coordinate;
    point = x;
    normal = vec3(0.0f);
    if (!viewpoint_coordinate(view, x, coordinate)) return false;
    ivec2 own = min(ivec2(coordinate), view.size - 1);
    ivec2 base = ivec2(floor(coordinate - 0.5f));
    bool interior = all(greaterThanEqual(base, ivec2(0))) && all(lessThan(base + 1, view.size));
    ivec2 low = clamp(base, ivec2(0), view.size - 1), high = clamp(base + 1, ivec2(0), view.size - 1);
    ivec2 corners[4] = ivec2[4](low, ivec2(high.x, low.y), ivec2(low.x, high.y), high);
    vec4 near_corner[4], far_corner[4];
    for (int k = 0; k < 4; ++k) {
        near_corner[k] = texelFetch(near_layer, corners[k], 0);
        far_corner[k] = texelFetch(far_layer, corners[k], 0);
    }
    // The texel holding x is a corner: own ∈ {base, base + 1} on each axis (clamped alike).
    bool own_high_x = own.x == high.x && own.x != low.x, own_high_y = own.y == high.y && own.y != low.y;
    vec4 own_near = own_high_y ? (own_high_x ? near_corner[3] : near_corner[2]) : (own_high_x ? near_corner[1] : near_corner[0]);
    vec4 own_far = own_high_y ? (own_high_x ? far_corner[3] : far_corner[2]) : (own_high_x ? far_corner[1] : far_corner[0]);
    if (own_near.w < 0.5f) return false;  // no surface here
    float d = viewpoint_distance(view, x);
    bool use_far = own_far.w > 0.5f && abs(d - own_far.z) < abs(d - own_near.z);
    LayerSample own_chosen = layer_value(use_far ? own_far : own_near);
    vec2 f = coordinate - 0.5f - vec2(base);
    vec3 blended_normal = vec3(0.0f);
    float blended_distance = 0.0f;
    bool same_surface = interior;
    for (int k = 0; k < 4; ++k) {
        LayerSample s = layer_value(use_far ? far_corner[k] : near_corner[k]);
        same_surface = same_surface && s.surface == own_chosen.surface;
        float weight = ((k & 1) == 1 ? f.x : 1.0f - f.x) * ((k >> 1) == 1 ? f.y : 1.0f - f.y);
        blended_normal += weight * (dot(s.normal, own_chosen.normal) < 0.0f ? -s.normal : s.normal);
        blended_distance += weight * s.distance;
    }
    float distance = same_surface ? blended_distance : own_chosen.distance;
    normal = same_surface ? normalize(blended_normal) : own_chosen.normal;
    point = view.orthographic ? x + (distance - d) * view.axis : view.eye + normalize(x - view.eye) * distance;
    return true;
}

struct LayerExit {
    bool found;    // false: the ray is still inside after the surface's extent (an open surface)
    float t;       // along the ray
    vec3 normal;   // outward: along the ray
};

// The exit within `reach` of x (found false: still inside there).
LayerExit find_layer_exit(Viewpoint view, vec3 x, vec3 d, int s, float reach) {
    float h = reach / float(kLayerMarchSteps);
    float inside_t = 0.0f, outside_t = -1.0f;
    for (int i = 1; i <= kLayerMarchSteps; ++i) {
        float t = float(i) * h;
        if (!inside_layers(view, x + t * d, s)) {
            outside_t = t;
            break;
        }
        inside_t = t;
    }
    // Without an exit the refinements below run no turn: a CPU rasterizer
    // leaves a loop that none of its lanes enters, where it would run the
    // code after an early return under a mask.
    bool found = outside_t >= 0.0f;
    for (int i = 0; i < (found ? kLayerBisections : 0); ++i) {
        float middle = 0.5f * (inside_t + outside_t);
        if (inside_layers(view, x + middle * d, s)) inside_t = middle;
        else outside_t = middle;
    }
    float t = 0.5f * (inside_t + outside_t);
    vec3 normal = vec3(0.0f);
    vec3 point;
    vec3 layer_normal;
    for (int i = 0; i < (found ? kTangentPlaneSteps : 0); ++i) {
        if (!nearest_layer_point(view, x + t * d, point, layer_normal)) break;
        normal = layer_normal;
        float approach = dot(d, layer_normal);
        if (abs(approach) < 1e-6f) break;
        float on_plane = dot(point - x, layer_normal) / approach;
        if (!(on_plane > 0.0f) || abs(on_plane - t) > 2.0f * h) break;  // a plane far off: keep the bisection's point
        t = on_plane;
    }
    if (!found) return LayerExit(false, reach, vec3(0.0f));
    if (normal == vec3(0.0f)) normal = -d;  // no layer found: leave undeflected below
    return LayerExit(true, t, dot(normal, d) < 0.0f ? -normal : normal);
}

// The exit of a ray inside surface s within `reach` of x: on its height
// field for a water body, else in the layers. Another surface within the
// water (a submerged object) shows in the layers alone: there the nearer
// of the two exits holds.
LayerExit find_exit(Viewpoint view, vec3 x, vec3 d, int s, float reach) {
#if EIKON_WATER_BODIES > 0
    int water = int(surface_extinction[surface_slot(s)].w);
    // Off the surface it entered by more than rounding (1 µm per metre of reach).
    WaterCrossing crossing = water_crossing(max(water, 0), x, d, 1e-6f * reach, reach, true);
    // The smooth normal may face the ray where it grazes out across a steep
    // facet: it is turned along the ray, as the layers' is.
    LayerExit on_water = LayerExit(crossing.found, crossing.t,
                                   dot(crossing.normal, d) < 0.0f ? -crossing.normal : crossing.normal);
#if EIKON_LAYER_SURFACES
    LayerExit in_layers = find_layer_exit(view, x, d, s, reach);
    bool layers_nearer = in_layers.found && (!on_water.found || in_layers.t < on_water.t);
    return water >= 0 && !layers_nearer ? on_water : in_layers;
#else
    return on_water;
#endif
#else
    return find_layer_exit(view, x, d, s, reach);
#endif
}

struct RefractorPath {
    vec3 x;           // where the ray left the surface, or where it ends inside
    vec3 d;           // the direction it leaves in (or ends in, at a receiver inside)
    vec3 throughput;  // Fresnel transmittance at the exit × Beer–Lambert inside
    ReceiverHit hit;  // a receiver met inside (hit.receiver ≥ 0): the ray ends there
    bool left;        // false: no way out was found (or the bounces ran out); the ray carries nothing on
    vec3 exit_normal; // where it left: the surface's normal, along the ray (left only)
};

// Follows a ray that entered surface s at x going d (already refracted into it).
RefractorPath follow_through_refractor(Viewpoint view, vec3 x, vec3 d, int s) {
    float n_inside = surface_index(s), n_outside = reference_index();
    vec3 kappa = surface_extinction[surface_slot(s)].rgb;
    RefractorPath path = RefractorPath(x, d, vec3(1.0f), ReceiverHit(-1, 2.0f, false, vec2(0.0f)), false, vec3(0.0f));
    for (int bounce = 0; bounce <= kInternalBounces; ++bounce) {
        // A receiver inside ends the search there: the march covers only the way to it.
        float reach = surface_reach(s);
        ReceiverHit hit = first_receiver_crossing(x, x + reach * d);
        float to_receiver = hit.receiver >= 0 ? hit.fraction * reach : reach;
        LayerExit exit_ = find_exit(view, x, d, s, to_receiver);
        if (hit.receiver >= 0 && !exit_.found) {
            path.x = x + to_receiver * d;
            path.d = d;
            path.throughput *= exp(-kappa * to_receiver);
            path.hit = hit;
            return path;
        }
        vec3 end = x + exit_.t * d;
        path.throughput *= exp(-kappa * exit_.t);
        if (!exit_.found) return path;
        float cos_i = dot(d, exit_.normal);
        vec3 out_d = refract(d, -exit_.normal, n_inside / n_outside);
        if (out_d != vec3(0.0f)) {
            float reflectance = surface_reflects(s) ? fresnel_reflectance(cos_i, n_inside, n_outside) : 0.0f;
            path.x = end;
            path.d = normalize(out_d);
            path.throughput *= 1.0f - reflectance;
            path.left = true;
            path.exit_normal = exit_.normal;
            return path;
        }
        x = end;  // totally reflected: on inside
        d = reflect(d, -exit_.normal);
    }
    return path;
}
