// The image-space camera view ([Hu07] §2; render/stages/ImageSpaceView.h):
// per pixel, the camera's surface layers give the first surface the ray
// meets, exactly where the raster pipeline drew it. There the ray splits by
// Fresnel into a reflection, which flies straight to a receiver or the
// environment, and a refraction, followed through the object to where it
// leaves (common/refractor_paths.glsl) and then straight on. A receiver
// shows albedo/π × the irradiance of the image-space caustic maps; the
// medium between surfaces is uniform (bridge/scene/ImageSpaceScope.h).
//
// Two passes, since a CPU rasterizer runs every branch of a work group
// under a mask: pass 0 (a work group per 8×8 pixels) draws every pixel that
// sees no surface and lists those that do; pass 1 (64 listed pixels per
// work group, dispatched indirectly) follows those through the surfaces.
// A GPU gains too: its work groups no longer mix short and long rays.
// Where the only sharp surfaces are water bodies, no layers are drawn:
// pass 2 (a work group per 8×8 pixels) meets each pixel's first surface on
// the bodies' height fields (common/water_height_fields.glsl), the walk the
// hulls' fragments would run, and draws every pixel; its work groups mix
// rays only along the water's edge.
//
// Program options: EIKON_PASS (0, 1 or 2), EIKON_ENVIRONMENT
// (layout::EnvironmentKind), EIKON_RECORD_EXIT (1: write each pixel's exit
// direction, for tests).
#if EIKON_PASS == 1
layout(local_size_x = 64) in;
#else
layout(local_size_x = 8, local_size_y = 8) in;
#endif

#include "common/grid_sampling.glsl"
#include "common/fresnel.glsl"
#include "common/receiver.glsl"
#include "common/receiver_blocks.glsl"
#include "common/refractor_paths.glsl"
#include "common/camera_block.glsl"
#include "common/environment.glsl"

#ifndef EIKON_RECORD_EXIT
#define EIKON_RECORD_EXIT 0
#endif

layout(std430, binding = kHdrImage) writeonly buffer HdrImage { vec4 hdr_radiance[]; };
#if EIKON_RECORD_EXIT
layout(std430, binding = kViewExit) writeonly buffer ViewExit { vec4 view_exit[]; };  // xyz direction; w: 1 escaped, 2 receiver
#endif

layout(std430, binding = kSurfacePixels) buffer SurfacePixels { uint surface_pixels[]; };  // y·width + x
layout(std430, binding = kSurfacePixelCount) buffer SurfacePixelCount {
    uvec4 surface_pixel_groups;  // x: work groups of pass 1 (y = z = 1); w: pixels listed
};

uniform mat4 view_projection;  // the camera's, as its layers were drawn

vec3 receiver_radiance(ReceiverHit hit) {
    if (!hit.lit_side) return vec3(0.0f);
    return receivers[receiver_slot(hit.receiver)].albedo.rgb / 3.14159265358979f * receiver_irradiance_at(hit.receiver, hit.map_uv);
}

// What a ray from x along d sees in the uniform medium: the first receiver, or the environment.
vec3 straight_radiance(vec3 x, vec3 d, out float kind) {
    float t;
    ReceiverHit hit = first_receiver_on_ray(x, d, EIKON_INFINITY, t);
    kind = hit.receiver >= 0 ? 2.0f : 1.0f;
    return hit.receiver >= 0 ? receiver_radiance(hit) : environment_radiance(x, d);
}

void write_pixel(uvec2 pixel, vec3 radiance, vec3 exit_direction, float exit_kind) {
    hdr_radiance[pixel.y * camera.image.x + pixel.x] = vec4(radiance, 1.0f);
#if EIKON_RECORD_EXIT
    view_exit[pixel.y * camera.image.x + pixel.x] = vec4(exit_direction, exit_kind);
#endif
}

#if EIKON_PASS == 2
// The nearest water body's surface the pixel's ray meets, as the hulls'
// fragments would have drawn it into the near layer.
LayerSample first_surface(uvec2 pixel) {
    vec3 d = camera_ray_direction(pixel);
    LayerSample first = LayerSample(vec3(0.0f, 1.0f, 0.0f), 1e30f, -1);
#if EIKON_WATER_BODIES > 0
    for (int body = 0; body < EIKON_WATER_BODIES; ++body) {
        WaterCrossing crossing = water_crossing(body, camera.position.xyz, d, 0.0f, first.distance, false);
        first = crossing.found && crossing.t < first.distance
                    ? LayerSample(crossing.normal, crossing.t, water_bodies[body].grid.w)
                    : first;
    }
#endif
    return first;
}
#else
LayerSample first_surface(uvec2 pixel) {
    return layer_sample(near_layer, ivec2(pixel.x, camera.image.y - 1u - pixel.y));
}
#endif

// A pixel whose ray meets no surface: straight on to a receiver or the environment.
void draw_without_surface(uvec2 pixel) {
    vec3 d = camera_ray_direction(pixel);
    float kind;
    vec3 radiance = straight_radiance(camera.position.xyz, d, kind);
    write_pixel(pixel, radiance, d, kind);
}

#if EIKON_PASS == 0
#include "common/listed_work_groups.glsl"

shared uint group_listed;  // this work group's pixels that see a surface
shared uint group_first;   // where they go in the list

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    bool inside_image = all(lessThan(pixel, camera.image.xy));
    bool listed = inside_image && first_surface(pixel).surface >= 0;
    // One atomic on the list's count per work group, not one per pixel
    // (every pixel of pool_caustics sees the water).
    if (gl_LocalInvocationIndex == 0u) group_listed = 0u;
    barrier();
    uint local_slot = listed ? atomicAdd(group_listed, 1u) : 0u;
    barrier();
    if (gl_LocalInvocationIndex == 0u && group_listed > 0u) {
        uint first = atomicAdd(surface_pixel_groups.w, group_listed);
        group_first = first;
        uint size = gl_WorkGroupSize.x * gl_WorkGroupSize.y;  // pass 1's work group, 64
        atomicAdd(surface_pixel_groups.x, work_groups_started(first, group_listed, size));
    }
    barrier();
    if (!inside_image) return;
    if (listed) {
        surface_pixels[group_first + local_slot] = pixel.y * camera.image.x + pixel.x;
        return;
    }
    draw_without_surface(pixel);
}
#else
// Follows a pixel's ray from the first surface it sees.
void draw_through_surface(uvec2 pixel, LayerSample first) {
    Viewpoint view;
    view.view_projection = view_projection;
    view.eye = camera.position.xyz;
    view.axis = camera.forward.xyz;
    view.orthographic = false;
    view.size = ivec2(camera.image.xy);
    vec3 d = camera_ray_direction(pixel);
    vec3 x = view.eye + first.distance * d;
    vec3 normal = dot(first.normal, d) > 0.0f ? -first.normal : first.normal;
    float n_outside = reference_index(), n_inside = surface_index(first.surface);
    float cos_i = -dot(d, normal);
    vec3 refracted = refract(d, normal, n_outside / n_inside);
    float reflectance = refracted == vec3(0.0f) ? 1.0f
                        : surface_reflects(first.surface) ? fresnel_reflectance(cos_i, n_outside, n_inside)
                                                          : 0.0f;
    // Two branches leave the surface: the reflection, straight on from x,
    // and the refraction, followed through the object. Each ends on a
    // receiver or in the environment, looked up from one call site each: a
    // CPU rasterizer runs every call site under a mask, taken or not.
    vec3 origin[2] = vec3[2](x + surface_offset() * normal, x);
    vec3 direction[2] = vec3[2](reflect(d, normal), d);
    vec3 weight[2] = vec3[2](vec3(reflectance), vec3(0.0f));
    ReceiverHit inside = ReceiverHit(-1, 2.0f, false, vec2(0.0f));
    bool refracted_on = reflectance < 1.0f;
    if (refracted_on) {
        RefractorPath path = follow_through_refractor(view, x, normalize(refracted), first.surface);
        origin[1] = path.x;
        direction[1] = path.d;  // the refracted branch, for tests
        weight[1] = (1.0f - reflectance) * path.throughput;
        inside = path.hit;
        refracted_on = path.hit.receiver >= 0 || path.left;
    }
    vec3 radiance = vec3(0.0f);
    float kind[2] = float[2](1.0f, 0.0f);  // 1 escaped, 2 receiver, 0 lost inside
    // Both turns always run (a loop of a constant count unrolls; one whose
    // count differs between lanes is bookkeeping every turn on a CPU).
    for (int branch = 0; branch < 2; ++branch) {
        bool on = branch == 0 || refracted_on;
        float t;
        ReceiverHit hit = branch == 1 && inside.receiver >= 0
                              ? inside
                              : first_receiver_on_ray(origin[branch], direction[branch], EIKON_INFINITY, t);
        kind[branch] = on ? (hit.receiver >= 0 ? 2.0f : 1.0f) : kind[branch];
        vec3 seen = hit.receiver >= 0 ? receiver_radiance(hit) : environment_radiance(origin[branch], direction[branch]);
        radiance += on ? weight[branch] * seen : vec3(0.0f);
    }
    // The exit recorded for tests: the refracted branch's where there is one.
    int recorded = reflectance < 1.0f ? 1 : 0;
    write_pixel(pixel, radiance, direction[recorded], kind[recorded]);
}

#if EIKON_PASS == 1
void main() {
    if (gl_GlobalInvocationID.x >= surface_pixel_groups.w) return;
    uint index = surface_pixels[gl_GlobalInvocationID.x];
    uvec2 pixel = uvec2(index % camera.image.x, index / camera.image.x);
    draw_through_surface(pixel, first_surface(pixel));
}
#else
void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, camera.image.xy))) return;
    LayerSample first = first_surface(pixel);
    if (first.surface >= 0) {
        draw_through_surface(pixel, first);
        return;
    }
    draw_without_surface(pixel);
}
#endif
#endif
