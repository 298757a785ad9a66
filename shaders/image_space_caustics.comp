// Image-space caustic maps ([Wyman06] §3.1–3.2; [Hu07] §3's caustic maps): a light's
// surface layers (common/surface_layers.glsl), drawn from the light over
// the scene's refractors, turn each of their texels into a photon that
// refracts through two interfaces (common/refractor_paths.glsl) and lands
// on a receiver. A photon carries the light's power over the texel's solid
// angle ([Wyman06] §3.2.1: E_B = E_L·ω_B/4π; a directional light's over the
// texel's area); it is splatted bilinearly into the four nearest texels of
// the receiver's 64-bit fixed-point tallies, which ReceiverMaps filters into
// W/m² as it does the eikonal photons'. The light no refractor intercepts is
// not sampled: the direct pass (EIKON_PASS 0) gives each receiver texel its
// exact irradiance I·cos θ/r² (E·cos θ for directional light), unless the
// light's layers show a refractor in front of it (then it arrives as
// photons) or another receiver shadows it, averaged over 4×4 points of the
// texel (a shadow's edge crosses texels).
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

layout(std430, binding = kReceiverTallies) buffer ReceiverTallies { uint receiver_tallies[]; };  // [2·(3·texel + channel) + word]

uniform mat4 view_projection;  // the light's, as its layers were drawn
uniform vec3 light_position;   // point, spot: the light; directional: a point of the layers' near plane
uniform vec3 light_axis;       // the layers' axis (directional: the direction light travels)
uniform int light_kind;        // 0 point, 1 spot, 2 directional
uniform vec3 light_intensity;  // point, spot: W/sr (a spot's on its axis); directional: W/m² ⟂ the light
uniform vec3 spot_axis;
uniform vec2 spot_cosines;     // cos outer (−2: no spot), cos inner
uniform vec3 frame_right;      // the layers' frame: texel (i, j) looks along axis + a·right + b·up
uniform vec3 frame_up;
uniform float frame_half_extent;  // perspective: tan of the half-angle; orthographic: half the width, m
uniform ivec2 layer_size;
uniform vec2 jitter;           // in texels, this frame's offset of the photons from the texel centres
uniform vec3 power_unit;       // W per tally unit
uniform uint texel_count;      // direct pass: receiver texels in all

const float kFarAway = 1e4f;

Viewpoint light_view() {
    Viewpoint view;
    view.view_projection = view_projection;
    view.eye = light_position;
    view.axis = light_axis;
    view.orthographic = light_kind == 2;
    view.size = layer_size;
    return view;
}

void deposit_texel(int r, ivec2 texel, vec3 watts) {
    int resolution = int(receivers[r].map.y);
    if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, ivec2(resolution)))) return;
    uint base = 6u * (receivers[r].map.x + uint(texel.y * resolution + texel.x));
    for (int c = 0; c < 3; ++c)
        if (watts[c] > 0.0f) ADD_WIDE_UNITS(receiver_tallies, base + uint(2 * c), wide_units(watts[c] / power_unit[c]));
}

// A photon's power on receiver hit.receiver, shared bilinearly between the four texels around it.
void splat(ReceiverHit hit, vec3 watts) {
    if (hit.receiver < 0 || !hit.lit_side) return;
    float resolution = float(receivers[hit.receiver].map.y);
    vec2 texel = hit.map_uv * resolution - 0.5f;
    ivec2 base = ivec2(floor(texel));
    vec2 f = texel - vec2(base);
    deposit_texel(hit.receiver, base, (1.0f - f.x) * (1.0f - f.y) * watts);
    deposit_texel(hit.receiver, base + ivec2(1, 0), f.x * (1.0f - f.y) * watts);
    deposit_texel(hit.receiver, base + ivec2(0, 1), (1.0f - f.x) * f.y * watts);
    deposit_texel(hit.receiver, base + ivec2(1, 1), f.x * f.y * watts);
}

vec3 intensity_toward(vec3 direction) {
    return light_intensity * spot_profile_about(spot_axis, spot_cosines.x, spot_cosines.y, direction);
}

#if EIKON_PASS == 0
const int kDirectSamples = 4;  // per texel edge: the shadow's edge is resolved to a sixteenth of a texel

// The irradiance at x on receiver r straight from the light, 0 where a
// refractor (its light arrives as photons) or another receiver is in the way.
vec3 direct_irradiance(int r, vec3 x) {
    vec3 normal = receivers[r].normal.xyz;
    vec3 toward_light = light_kind == 2 ? -light_axis : normalize(light_position - x);
    float cos_theta = dot(toward_light, normal);
    if (cos_theta <= 0.0f) return vec3(0.0f);  // the light is behind this receiver
    vec3 from = light_kind == 2 ? x + kFarAway * toward_light : light_position;
    float distance = length(from - x);
    ReceiverHit blocker = first_receiver_crossing(from, x + 1e-5f * normal);
    if (blocker.receiver >= 0 && blocker.fraction * distance < distance * (1.0f - 1e-5f)) return vec3(0.0f);
    ivec2 texel;
    Viewpoint view = light_view();
    if (viewpoint_texel(view, x, texel)) {
        LayerSample first = layer_sample(near_layer, texel);
        if (first.surface >= 0 && first.distance < viewpoint_distance(view, x)) return vec3(0.0f);
    }
    return light_kind == 2 ? light_intensity * cos_theta
                           : intensity_toward(-toward_light) * cos_theta / (distance * distance);
}

void main() {
    uint index = gl_GlobalInvocationID.y * gl_NumWorkGroups.x * gl_WorkGroupSize.x + gl_GlobalInvocationID.x;
    if (index >= texel_count) return;
    int r = 0;
    while (r + 1 < int(receiver_count) && index >= receivers[r + 1].map.x) ++r;
    uint resolution = receivers[r].map.y;
    uint local = index - receivers[r].map.x;
    ivec2 texel = ivec2(local % resolution, local / resolution);
    float size = receivers[r].origin.w;
    vec3 sum = vec3(0.0f);
    for (int j = 0; j < kDirectSamples; ++j)
        for (int i = 0; i < kDirectSamples; ++i) {
            vec2 uv = (vec2(texel) + (vec2(i, j) + 0.5f) / float(kDirectSamples)) / float(resolution);
            vec3 x = receivers[r].origin.xyz + (uv.x - 0.5f) * size * receivers[r].axis_u.xyz +
                     (uv.y - 0.5f) * size * receivers[r].axis_v.xyz;
            sum += direct_irradiance(r, x);
        }
    deposit_texel(r, texel, sum / float(kDirectSamples * kDirectSamples) * receivers[r].normal.w);
}
#else
void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, layer_size))) return;
    LayerSample first = layer_sample(near_layer, texel);
    if (first.surface < 0) return;  // this light reaches the receivers directly
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
    if (reflectance > 0.0f)
        splat(first_receiver_crossing(x + 1e-5f * normal, x + kFarAway * reflect(d, normal)), reflectance * watts);
    if (reflectance >= 1.0f) return;
    RefractorPath path = follow_through_refractor(view, x, normalize(refracted), first.surface);
    vec3 carried = (1.0f - reflectance) * path.throughput * watts;
    if (path.hit.receiver >= 0) splat(path.hit, carried);
    else if (path.left) splat(first_receiver_crossing(path.x, path.x + kFarAway * path.d), carried);
}
#endif
