// Image-space caustic maps ([Wyman06] §3.1–3.2; [Hu07] §3's caustic maps): a light's
// surface layers (common/surface_layers.glsl), drawn from the light over
// the scene's refractors, turn each of their texels into a photon that
// refracts through two interfaces (common/refractor_paths.glsl) and lands
// on a receiver. A photon carries the light's power over the texel's solid
// angle ([Wyman06] §3.2.1: E_B = E_L·ω_B/4π; a directional light's over the
// texel's area). The photon pass (EIKON_PASS 1) records each photon's last
// straight flight and the receiver it lands on, refracted and reflected
// (common/caustic_vertices.glsl); caustic_polygons.comp joins neighbouring
// photons into triangles that carry the power between them
// (render/stages/CausticPolygons.h). The light
// no refractor intercepts is not sampled: the direct pass (EIKON_PASS 0)
// gives each receiver texel its exact irradiance I·cos θ/r² (E·cos θ for
// directional light), unless the light's layers show a refractor in front
// of it (then it arrives through the caustic maps) or another receiver
// shadows it, averaged over the texel (4×4 points where a shadow's edge
// crosses it).
//
// Program options: EIKON_PASS (0: direct, one invocation per receiver texel;
// 1: photons, one per light texel).
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/grid_sampling.glsl"
#include "common/fresnel.glsl"
#include "common/receiver.glsl"
#include "common/receiver_blocks.glsl"
#include "common/refractor_paths.glsl"
#include "common/emitters.glsl"
#include "common/wide_units.glsl"
#include "common/caustic_deposits.glsl"
#include "common/caustic_vertices.glsl"

uniform mat4 view_projection;  // the light's, as its layers were drawn
uniform vec3 light_position;   // point, spot: the light; directional: a point of the layers' near plane
uniform vec3 light_axis;       // the layers' axis (directional: the direction light travels)
uniform int light_kind;        // 0 point, 1 spot, 2 directional
uniform vec3 light_intensity;  // point, spot: W/sr (a spot's on its axis); directional: W/m² ⟂ the light
uniform vec3 spot_axis;
uniform vec2 spot_versines;    // 1 − cos of the outer half-angle (< 0: no spot), of the inner
uniform vec3 frame_right;      // the layers' frame: texel (i, j) looks along axis + a·right + b·up
uniform vec3 frame_up;
uniform float frame_half_extent;  // perspective: tan of the half-angle; orthographic: half the width, m
uniform ivec2 layer_size;
uniform vec2 jitter;           // in texels, this frame's offset of the photons from the texel centres
uniform uint texel_count;      // direct pass: receiver texels in all

#if EIKON_PASS == 1
// The cell pass's work groups (CausticPolygons.h): z, its sheets, becomes 2
// once a reflected photon lands (a plain store: every writer writes 2).
layout(std430, binding = kCausticCellGroups) writeonly buffer CausticCellGroups { uvec4 caustic_cell_groups; };
#endif

Viewpoint light_view() {
    Viewpoint view;
    view.view_projection = view_projection;
    view.eye = light_position;
    view.axis = light_axis;
    view.orthographic = light_kind == 2;
    view.size = layer_size;
    return view;
}

vec3 intensity_toward(vec3 direction) {
    return light_intensity * spot_profile_about(spot_axis, spot_versines.x, spot_versines.y, direction);
}

#if EIKON_PASS == 0
const int kDirectSamples = 4;  // per texel edge: the shadow's edge is resolved to a sixteenth of a texel

// The irradiance at x on receiver r straight from the light, were nothing in the way.
vec3 unblocked_irradiance(int r, vec3 x) {
    vec3 toward_light = light_kind == 2 ? -light_axis : normalize(light_position - x);
    float cos_theta = dot(toward_light, receivers[r].normal.xyz);
    if (cos_theta <= 0.0f) return vec3(0.0f);  // the light is behind this receiver
    if (light_kind == 2) return light_intensity * cos_theta;
    float distance = length(light_position - x);
    return intensity_toward(-toward_light) * cos_theta / (distance * distance);
}

// Whether a refractor (its light arrives through the caustic maps) or
// another receiver stands between the light and x on receiver r.
bool light_blocked(int r, vec3 x) {
    vec3 normal = receivers[r].normal.xyz;
    // Another receiver (a lone one stands only before its own back, where
    // unblocked_irradiance gives nothing), met on the way from x, just off
    // its square, to the light however far that is.
    if (receiver_count > 1u) {
        vec3 toward_light = light_kind == 2 ? -light_axis : normalize(light_position - x);
        float reach = light_kind == 2 ? EIKON_INFINITY : length(light_position - x);
        float t;
        ReceiverHit blocker = first_receiver_on_ray(x + 1e-5f * receivers[r].origin.w * normal, toward_light, reach, t);
        if (blocker.receiver >= 0 && t < reach * (1.0f - 1e-5f)) return true;
    }
    ivec2 texel;
    Viewpoint view = light_view();
    if (!viewpoint_texel(view, x, texel)) return false;
    LayerSample first = layer_sample(near_layer, texel);
    return first.surface >= 0 && first.distance < viewpoint_distance(view, x);
}

vec3 receiver_point(int r, vec2 uv) {
    float size = receivers[r].origin.w;
    return receivers[r].origin.xyz + (uv.x - 0.5f) * size * receivers[r].axis_u.xyz +
           (uv.y - 0.5f) * size * receivers[r].axis_v.xyz;
}

void main() {
    int r;
    ivec2 texel;
    if (!receiver_texel_of_invocation(texel_count, r, texel)) return;
    float resolution = float(receivers[r].map.y);
    // The texel's corners and centre first: where they agree, no shadow edge
    // crosses it (a shadow narrower than half a texel can slip between them)
    // and the 4×4 points need no test of their own.
    const vec2 probes[5] = vec2[5](vec2(0.0f), vec2(1.0f, 0.0f), vec2(0.0f, 1.0f), vec2(1.0f), vec2(0.5f));
    bool blocked = false, edge = false;
    for (int k = 0; k < 5; ++k) {  // one call site (a CPU rasterizer runs each under a mask)
        bool probe = light_blocked(r, receiver_point(r, (vec2(texel) + probes[k]) / resolution));
        if (k == 0) blocked = probe;
        else edge = edge || probe != blocked;
    }
    if (blocked && !edge) return;
    // A texel in full light averages its smooth irradiance over 2×2
    // Gauss–Legendre points (exact for a bicubic); one a shadow's edge
    // crosses, over 4×4 points each tested for shadow. Two loops, each run
    // no turn where it does not apply: a CPU rasterizer leaves a loop none
    // of its lanes enters, but runs a skipped call (the shadow test) under
    // a mask.
    vec3 sum = vec3(0.0f);
    for (int k = 0; k < (edge ? 0 : 4); ++k) {
        vec2 at = 0.5f + (vec2(k % 2, k / 2) - 0.5f) / sqrt(3.0f);
        sum += unblocked_irradiance(r, receiver_point(r, (vec2(texel) + at) / resolution));
    }
    for (int k = 0; k < (edge ? kDirectSamples * kDirectSamples : 0); ++k) {
        vec2 at = (vec2(k % kDirectSamples, k / kDirectSamples) + 0.5f) / float(kDirectSamples);
        vec3 x = receiver_point(r, (vec2(texel) + at) / resolution);
        if (!light_blocked(r, x)) sum += unblocked_irradiance(r, x);
    }
    int samples = edge ? kDirectSamples : 2;
    deposit_texel(r, texel, sum / float(samples * samples) * receivers[r].normal.w);
}
#else
// A photon's last straight flight, from `origin` along `direction`, the
// receiver it lands on (`hit`, if on its lit side) and the power it carries:
// the cells it bounds carry that power whether or not it lands itself.
CausticVertex landing(ReceiverHit hit, int surface, vec3 origin, vec3 direction, vec3 watts, vec3 entry_normal,
                     vec3 exit_normal) {
    return CausticVertex(hit.receiver >= 0 && hit.lit_side ? hit.receiver : -1, surface, origin, direction, watts,
                         entry_normal, exit_normal);
}

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, layer_size))) return;
    uint index = uint(texel.y * layer_size.x + texel.x);
    CausticVertex refracted_vertex =
        CausticVertex(-1, -1, vec3(0.0f), vec3(0.0f, -1.0f, 0.0f), vec3(0.0f), vec3(0.0f, 0.0f, 1.0f), vec3(0.0f, 0.0f, 1.0f));
    CausticVertex reflected_vertex = refracted_vertex;
    LayerSample first = layer_sample(near_layer, texel);
    if (first.surface >= 0) {  // otherwise this light reaches the receivers directly
        vec2 ndc = (vec2(texel) + 0.5f + jitter) / vec2(layer_size) * 2.0f - 1.0f;
        Viewpoint view = light_view();
        vec3 origin, d;
        vec3 watts;
        float texel_edge = 2.0f * frame_half_extent / float(layer_size.x);
        if (view.orthographic) {
            origin = light_position + frame_half_extent * (ndc.x * frame_right + ndc.y * frame_up);
            d = light_axis;
            watts = light_intensity * texel_edge * texel_edge;
        } else {
            vec2 slope = frame_half_extent * ndc;
            origin = light_position;
            d = normalize(light_axis + slope.x * frame_right + slope.y * frame_up);
            // dω of a texel of a plane at unit distance: dA·cos³θ = dA/(1 + a² + b²)^{3/2}.
            float solid_angle = texel_edge * texel_edge * pow(1.0f + dot(slope, slope), -1.5f);
            watts = intensity_toward(d) * solid_angle;
        }
        // The photon meets the surface the texel shows at that surface's tangent plane.
        vec3 drawn = view.orthographic ? origin + (first.distance - dot(origin - light_position, light_axis)) * light_axis
                                       : light_position + first.distance * d;
        vec3 normal = dot(first.normal, d) > 0.0f ? -first.normal : first.normal;
        float along = dot(drawn - origin, normal) / dot(d, normal);
        vec3 x = origin + (along > 0.0f ? along : dot(drawn - origin, d)) * d;
        float n_outside = reference_index(), n_inside = surface_index(first.surface);
        vec3 refracted = refract(d, normal, n_outside / n_inside);
        float reflectance = refracted == vec3(0.0f) ? 1.0f
                            : surface_reflects(first.surface) ? fresnel_reflectance(-dot(d, normal), n_outside, n_inside)
                                                              : 0.0f;
        // Two branches leave the surface: the refraction, followed through
        // the object, and the reflection, straight on from x. Each lands
        // from one call site (a CPU rasterizer runs every call site under a
        // mask, taken or not).
        vec3 start[2] = vec3[2](x, x + surface_offset() * normal);
        vec3 heading[2] = vec3[2](d, reflect(d, normal));
        vec3 carried[2] = vec3[2](vec3(0.0f), reflectance * watts);
        vec3 left_through[2] = vec3[2](normal, normal);  // the refraction's exit normal, once found
        ReceiverHit inside = ReceiverHit(-1, 2.0f, false, vec2(0.0f));
        bool refracted_on = reflectance < 1.0f;
        if (refracted_on) {
            RefractorPath path = follow_through_refractor(view, x, normalize(refracted), first.surface);
            start[0] = path.x;
            heading[0] = path.d;
            carried[0] = (1.0f - reflectance) * path.throughput * watts;
            inside = path.hit;
            refracted_on = path.hit.receiver >= 0 || path.left;
            left_through[0] = path.left ? path.exit_normal : normal;
        }
        // Both turns always run: a loop of a constant count unrolls, where
        // one whose start or end differs between lanes costs a CPU
        // rasterizer its bookkeeping every turn.
        for (int sheet = 0; sheet < 2; ++sheet) {
            bool on = sheet == 0 ? refracted_on : reflectance > 0.0f;
            float t;
            ReceiverHit hit = sheet == 0 && inside.receiver >= 0
                                  ? inside
                                  : first_receiver_on_ray(start[sheet], heading[sheet], EIKON_INFINITY, t);
            CausticVertex landed =
                landing(hit, first.surface, start[sheet], heading[sheet], carried[sheet], normal, left_through[sheet]);
            if (on && sheet == 0) refracted_vertex = landed;
            if (on && sheet == 1) reflected_vertex = landed;
        }
    }
    write_caustic_vertex(index, 0, refracted_vertex);
    write_caustic_vertex(index, 1, reflected_vertex);
    if (reflected_vertex.receiver >= 0) caustic_cell_groups.z = 2u;
    // caustic_polygons.comp spreads a quarter of each vertex's power over each
    // of the (up to four) cells of the light's grid it is a corner of; a
    // vertex on the grid's edge lands the share of the cells it lacks here.
    int cells = (texel.x > 0 && texel.x + 1 < layer_size.x ? 2 : 1) * (texel.y > 0 && texel.y + 1 < layer_size.y ? 2 : 1);
    float missing = float(4 - cells) / 4.0f;
    for (int sheet = 0; sheet < 2 && missing > 0.0f; ++sheet) {
        CausticVertex v = sheet == 0 ? refracted_vertex : reflected_vertex;
        vec2 map_uv;
        if (v.receiver >= 0 && flight_on_plane(v, receiver_plane(v.receiver), map_uv))
            splat_at(v.receiver, map_uv, missing * v.watts);
    }
}
#endif
