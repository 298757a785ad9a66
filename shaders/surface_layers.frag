// One layer of depth peeling (common/surface_layers.glsl): peel 0 keeps the
// nearest surface of every texel; peel 1 the nearest one farther than the
// first layer's by more than a rounding gap (the depth test keeps the
// nearest of what passes). A sphere is exact, as everywhere in eikon: its
// tessellation is drawn a little larger than the sphere (ShapeTriangles.h),
// and each fragment meets the sphere itself along its texel's ray —
// entering on peel 0, leaving on peel 1 — with the sphere's own normal, or
// is discarded where that ray misses it.
//
// Program options: EIKON_PEEL (0 or 1); EIKON_NEAR_TEST (peel 1: 1 peels
// behind the first layer; 0 where only the faces away from the viewpoint
// are drawn, whose nearest lies behind the first layer already:
// SurfaceRaster::drawsFacingFaces); EIKON_EXACT_SHAPES (1: the spheres' and
// boxes' triangles, whose spheres are met exactly; 0: meshes, drawn as they
// are; 2: the water bodies' hulls, in which each fragment walks its texel's
// ray over the body's height field (common/water_height_fields.glsl) to
// the first crossing, or on peel 1 the first behind the first layer, and
// writes that crossing's depth). Each is its own program because a CPU rasterizer runs
// every branch under a mask, and a discard anywhere in the program turns its
// early depth test off: mesh fragments then pay for neither, except in a
// peel that tests the first layer.
#include "common/surface_layers.glsl"
#include "common/sharp_surface_list.glsl"
#include "common/sharp_surfaces.glsl"
#if EIKON_EXACT_SHAPES == 2
#include "common/water_height_fields.glsl"
uniform mat4 view_projection;
uniform int water_of_surface[kMaxSharpObjects];  // a surface's water body
#endif

in vec3 world_position;
in vec3 corner_normal;
flat in int surface;

uniform vec3 view_eye;
uniform vec3 view_axis;
uniform int view_orthographic;
#if EIKON_PEEL == 1 && (EIKON_NEAR_TEST || EIKON_EXACT_SHAPES == 2)
layout(binding = kNearLayerTexture) uniform sampler2D near_layer;
#endif

layout(location = 0) out vec4 layer;

void main() {
    Viewpoint view;
    view.eye = view_eye;
    view.axis = view_axis;
    view.orthographic = view_orthographic != 0;
    vec3 x = world_position;
    vec3 normal = normalize(corner_normal);
#if EIKON_EXACT_SHAPES == 2
    vec3 origin = view.orthographic ? x - dot(x - view.eye, view.axis) * view.axis : view.eye;
    vec3 d = view.orthographic ? view.axis : normalize(x - view.eye);
    float from = 0.0f;  // along the ray: the eye, or the orthographic view's near plane
#if EIKON_PEEL == 1
    vec4 nearer = texelFetch(near_layer, ivec2(gl_FragCoord.xy), 0);
    from = nearer.w > 0.5f ? nearer.z * (1.0f + 1e-5f) : 0.0f;  // the peel's gap, relative: any scale
#endif
    WaterCrossing crossing = water_crossing(water_of_surface[surface], origin, d, from, 1e30f, false);
    if (!crossing.found) discard;
    x = origin + crossing.t * d;
    normal = crossing.normal;
    vec4 clip = view_projection * vec4(x, 1.0f);
    gl_FragDepth = clamp(0.5f * clip.z / clip.w + 0.5f, 0.0f, 1.0f);
#elif EIKON_EXACT_SHAPES
    SharpSurface shape = sharp_surfaces[surface];
    if (surface_kind(shape.shape_a) == kSharpSphere) {
        vec3 origin = view.orthographic ? x - dot(x - view.eye, view.axis) * view.axis : view.eye;
        vec3 d = view.orthographic ? view.axis : normalize(x - view.eye);
        float t = surface_crossing(shape.shape_a, shape.shape_b, origin, d, EIKON_PEEL == 1, -1e30f);
        if (t == EIKON_NO_CROSSING || (EIKON_PEEL == 1 && t == 0.0f)) discard;
        x = origin + t * d;
        normal = surface_normal(shape.shape_a, shape.shape_b, x);
    }
#endif
    float distance = viewpoint_distance(view, x);
#if EIKON_PEEL == 1 && EIKON_NEAR_TEST && EIKON_EXACT_SHAPES != 2
    vec4 nearer = texelFetch(near_layer, ivec2(gl_FragCoord.xy), 0);
    if (distance <= nearer.z * (1.0f + 1e-5f)) discard;
#endif
    layer = vec4(octahedral_encode(normal), distance, float(surface + 1));
}
