// Viewing pass (Sun et al. 2008, §4.5; image formation of Ihrke et al. 2007,
// §3): one camera ray per pixel, bent by the same ray equation as photons
// inside the field grid, straight outside it. Along the way it gathers
// in-scattered light σs·φ·p with an isotropic phase function (p = 1/4π)
// under the Beer–Lambert transmittance; a receiver it meets shows
// albedo/π × its photon irradiance; a ray that escapes sees the background.
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/grid_sampling.glsl"
#include "common/ray_step.glsl"
#include "common/attenuation.glsl"
#include "common/phase.glsl"
#include "common/receiver.glsl"
#include "common/receiver_blocks.glsl"
#include "common/straight_flight.glsl"

layout(std140, binding = 1) uniform CameraBlock {
    vec4 position;    // w: tan(fov / 2)
    vec4 forward;     // w: aspect
    vec4 right;
    vec4 up;
    vec4 background;  // rgb radiance
    uvec4 image;      // width, height
} camera;

#if EIKON_HAS_SCATTERING
layout(std430, binding = 5) readonly buffer Fluence { float fluence[]; };
#endif
layout(std430, binding = 7) writeonly buffer HdrImage { vec4 hdr_radiance[]; };

uniform float step_length;
uniform uint max_steps;

vec3 in_scattered_radiance(vec3 x) {
#if EIKON_HAS_SCATTERING
    uint index = 3u * uint(grid_linear_index(grid_cell(x)));
    vec3 phi = vec3(fluence[index], fluence[index + 1u], fluence[index + 2u]);
    return sample_scattering(x) * phi * henyey_greenstein(0.0f, 0.0f);
#else
    return vec3(0.0f);
#endif
}

vec3 receiver_radiance(ReceiverHit hit) {
    if (!hit.lit_side) return vec3(0.0f);
    return receivers[hit.receiver].albedo.rgb / 3.14159265358979f * receiver_irradiance_at(hit.receiver, hit.map_uv);
}

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, camera.image.xy))) return;
    vec2 ndc = (vec2(pixel) + 0.5f) / vec2(camera.image.xy) * 2.0f - 1.0f;
    vec3 direction = normalize(camera.forward.xyz + ndc.x * camera.position.w * camera.forward.w * camera.right.xyz -
                               ndc.y * camera.position.w * camera.up.xyz);
    vec3 x = camera.position.xyz;
    vec3 x_lost = vec3(0.0f);  // Kahan compensation of x
    vec3 v = reference_index() * direction;
    vec3 radiance = vec3(0.0f);
    vec3 transmittance = vec3(1.0f);
    uint steps = 0u;
    bool done = false;

    while (!done) {
        if (!grid_contains(x)) {
            vec3 d = normalize(v);
            StraightFlight flight = fly_straight(x, d);
            if (flight.hit.receiver >= 0) {
                radiance += transmittance * receiver_radiance(flight.hit);
                done = true;
            } else if (!flight.enters_grid) {
                radiance += transmittance * camera.background.rgb;
                done = true;
            } else {
                x = grid_entry_point(x, d, flight);
                x_lost = vec3(0.0f);
                if (grid_contains(x)) v = (reference_index() + sample_gradient_and_delta(x).w) * d;
            }
            continue;
        }
        if (steps >= max_steps) break;
        vec4 field = sample_gradient_and_delta(x);
        vec3 start = x;
        eikonal_euler_step(x, x_lost, v, reference_index() + field.w, field.xyz, step_length);
        ++steps;
        ReceiverHit hit = first_receiver_crossing(start, x);
        float travelled = hit.receiver >= 0 ? hit.fraction * step_length : step_length;
        vec3 kappa = sample_extinction(start);
        radiance += transmittance * in_scattered_radiance(start) * attenuated_track_length(kappa, travelled);
        transmittance *= beer_lambert_transmittance(kappa, travelled);
        if (hit.receiver >= 0) {
            radiance += transmittance * receiver_radiance(hit);
            done = true;
        } else if (!grid_contains(x)) {
            v = reference_index() * normalize(v);
        }
    }
    hdr_radiance[pixel.y * camera.image.x + pixel.x] = vec4(radiance, 1.0f);
}
