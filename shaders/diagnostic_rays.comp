// Diagnostics (docs/scene-format.md, `diagnostic`): parallel light through
// the test volume, one ray per pixel from the orthographic camera's image
// plane along its axis, marched through the graded field by the camera
// rays' leapfrog (common/integrators.glsl; view_rays.comp) with fixed steps
// of `step_length`, the last one cut at the grid's far face. Along the way it
// sums the optical path difference OPD = ∫ (n − n_ref) ds by the trapezoid
// rule over each step (second order, as the leapfrog is); where it leaves
// the grid (the medium is uniform beyond) its deflection ε is the change of
// its unit direction on the image's right and up axes. Where the scene
// has extinction it also sums the optical depth ∫κ ds, by the same rule.
// The instrument (common/diagnostic_instruments.glsl) turns (OPD, ε, the
// transmittance) into the pixel's I/I₀.
//
// The ray is marched in the camera's frame (x right, y up, z forward), the
// field's gradient turned into it, so that ε — parts in 1e4 of a unit
// vector — is carried in float32 with its own precision rather than as the
// difference of two world directions near 1; and OPD sums δn as the field
// holds it, since n_ref + δn in float32 rounds δn.
//
// Writes per pixel (ε_right, ε_up, OPD, how the ray ended: 1 crossed the
// grid, 2 missed it, 0 cut by the step cap or the loop budget), the linear
// I/I₀ (HdrImage) and its sRGB encoding (LdrImage); row 0 at the top.
// Program options: EIKON_INSTRUMENT, EIKON_HAS_EXTINCTION, EIKON_LOOP_BUDGET.
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/grid_sampling.glsl"
#include "common/loop_budget.glsl"
#include "common/ray_step.glsl"
#include "common/camera_block.glsl"
#include "common/srgb.glsl"
#include "common/diagnostic_instruments.glsl"

vec3 ray_origin;      // world position of the ray's frame's origin, where it entered the grid
float sampled_delta;  // δn at field_at's latest point

vec3 world_direction(vec3 local) {
    return local.x * camera.right.xyz + local.y * camera.up.xyz + local.z * camera.forward.xyz;
}

// (∇n, n) at a point of the ray's frame, the gradient on the frame's axes.
vec4 field_at(vec3 local) {
    vec4 sample_ = sample_gradient_and_delta(ray_origin + world_direction(local));
    sampled_delta = sample_.w;
    vec3 gradient = sample_.xyz;
    return vec4(dot(gradient, camera.right.xyz), dot(gradient, camera.up.xyz), dot(gradient, camera.forward.xyz),
                reference_index() + sample_.w);
}

#include "common/integrators.glsl"

layout(std430, binding = kDiagnosticRays) writeonly buffer DiagnosticRays { vec4 rays[]; };
layout(std430, binding = kHdrImage) writeonly buffer HdrImage { vec4 hdr_radiance[]; };
layout(std430, binding = kLdrImage) writeonly buffer LdrImage { uint ldr_rgba8[]; };

uniform float step_length;
uniform uint max_steps;

const float kRayCut = 0.0f;
const float kRayCrossed = 1.0f;
const float kRayMissed = 2.0f;

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, camera.image.xy))) return;
    vec3 start = camera_ray_origin(pixel);
    vec2 span = grid_ray_interval(start, camera.forward.xyz);
    float opd = 0.0f;
    vec3 optical_depth = vec3(0.0f);
    vec2 deflection = vec2(0.0f);
    float ended = kRayMissed;
    if (span.x < span.y && span.y > 0.0f) {
        ended = kRayCut;
        ray_origin = start + max(span.x, 0.0f) * camera.forward.xyz;
        vec3 x = vec3(0.0f);
        vec3 x_lost = vec3(0.0f);  // Kahan compensation of x
        vec4 field = field_at(x);
        vec3 v = vec3(0.0f, 0.0f, field.w);
        float delta_before = sampled_delta;
#if EIKON_HAS_EXTINCTION
        vec3 kappa_before = sample_extinction(ray_origin);
#endif
        float exit_tolerance = 1e-3f * min(min(grid.voxel_size.x, grid.voxel_size.y), grid.voxel_size.z);
        // The straight ray's way through the grid. A bent ray needs at least
        // as long to reach the far face, so the face is looked for along the
        // ray's own direction only over its last two steps (a slab test each
        // step cost a fifth of the pass); one that leaves by another face
        // first ends where its step took it out.
        float chord = span.y - max(span.x, 0.0f);
        float travelled = 0.0f;
        for (uint steps = 0u; steps < max_steps; ++steps) {
            spend_loops(1u);
            if (!loops_left()) break;
            float ds = step_length;
            if (travelled + 2.0f * step_length >= chord) {
                // NaN (a ray along a face) counts as out.
                float remaining = grid_ray_interval(ray_origin + world_direction(x), world_direction(normalize(v))).y;
                if (!(remaining > exit_tolerance)) {
                    ended = kRayCrossed;
                    break;
                }
                ds = min(step_length, remaining);
            }
            integrate_leapfrog(x, x_lost, v, field, ds);
            travelled += ds;
            opd += 0.5f * (delta_before + sampled_delta) * ds;
            delta_before = sampled_delta;
#if EIKON_HAS_EXTINCTION
            vec3 kappa = sample_extinction(ray_origin + world_direction(x));
            optical_depth += 0.5f * (kappa_before + kappa) * ds;
            kappa_before = kappa;
#endif
            if (!grid_contains(ray_origin + world_direction(x))) {
                ended = kRayCrossed;
                break;
            }
        }
        deflection = normalize(v).xy;
    }
    uint i = pixel.y * camera.image.x + pixel.x;
    rays[i] = vec4(deflection, opd, ended);
    float u = (float(pixel.x) + 0.5f) / float(camera.image.x);
    vec3 intensity = instrument_intensity(opd, deflection, u, exp(-optical_depth));
    hdr_radiance[i] = vec4(intensity, 1.0f);
    ldr_rgba8[i] = packUnorm4x8(vec4(srgb_encode(intensity), 1.0f));
}
