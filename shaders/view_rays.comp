// Viewing pass ([Sun08] §4.5; image formation of [Ihrke07] §3 and §5.3):
// one camera ray per pixel, bent by the same ray equation as
// photons inside the field grid (leapfrog: one field sample per step, and
// second order — Euler's one-voxel steps misplaced a totally reflected ray
// by 6°), straight outside it. Inside media it steps
// render.step_voxels voxels (one by default: no voxel is missed and
// neighbouring pixels agree) — on voxels that are boxes, that many along
// each axis, the ray's bend included (common/step_size.glsl); through nodes
// of the step structure that are uniform in index and empty of extinction
// it jumps to the node's face.
// Along the way it gathers in-scattered light σs·φ·p(θ) — Henyey–Greenstein
// against the stored mean photon direction — under the Beer–Lambert
// transmittance, and at interfaces the environment reflected about ∇n/|∇n|
// weighted by the Fresnel term (total internal reflection is left to the ray
// equation). A receiver it meets shows albedo/π × its photon irradiance; a
// ray that escapes sees the environment. A glowing medium adds its emission
// ε ([Ihrke07] §3, L_e) under the same transmittance as in-scattering:
// each step gathers (σs·φ·p + ε)·∫exp(−κs)ds. At a sharp surface
// (common/sharp_surfaces.glsl) a step ends exactly there and the ray splits
// into its Fresnel-weighted reflection and refraction, both traced, until
// `surface_depth` surface events; past that it follows the stronger branch.
// A preview (pixel_stride k > 1, the viewer while the camera moves) traces
// one ray per k×k block of pixels, through the pixel nearest the block's
// centre, and fills the block with it; k = 1 is the image itself.
// A pass traces one ray a pixel, through the point `sample_offset` of it
// (render/stages/PixelSamples.h); the image is the running mean of the
// `samples_before` passes before it and this one — a box filter over the pixel.
// The environment's checkerboard is filtered over the share of the pixel a
// ray stands for (`footprint_pixels` pixels wide; common/environment.glsl),
// spread as a straight ray from the camera spreads over the distance from
// the camera to where it looks up the environment: media and surfaces that
// focus or spread the ray change its true footprint, which the samples then
// cover.
//
// Program options: EIKON_HAS_EXTINCTION, EIKON_HAS_SCATTERING,
// EIKON_HAS_ANISOTROPY, EIKON_HAS_EMISSION, EIKON_MULTIPLE_SCATTERING (1: add the
// lattice's multiply scattered fluence, σs·φ_ms/(4π)), EIKON_STEP_STRUCTURE (1: large steps through empty
// nodes), EIKON_FRESNEL, EIKON_ENVIRONMENT (layout::EnvironmentKind),
// EIKON_SHARP_SURFACES (0 none, 1 spheres and boxes, 2 meshes or water too),
// EIKON_RECORD_EXIT (1: write each pixel's exit direction from the first pass, for tests).
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/grid_sampling.glsl"
#include "common/loop_budget.glsl"
#include "common/ray_step.glsl"
#include "common/attenuation.glsl"
#include "common/phase.glsl"
#include "common/fresnel.glsl"
#include "common/step_size.glsl"
#include "common/receiver.glsl"
#include "common/receiver_blocks.glsl"
#include "common/straight_flight.glsl"
#include "common/sharp_surfaces.glsl"

#ifndef EIKON_SHARP_SURFACES
#define EIKON_SHARP_SURFACES 0
#endif

float sharp_offset = 0.0f;  // δn the sharp objects the ray is inside add to the graded field

vec4 field_at(vec3 x) {
    vec4 sample_ = sample_gradient_and_delta(x);
    return vec4(sample_.xyz, reference_index() + sample_.w + sharp_offset);
}

#if EIKON_SHARP_SURFACES
#include "common/sharp_surface_blocks.glsl"
uniform uint surface_depth;  // surface events that split a ray in two; at most MAX_PENDING
#endif

#include "common/integrators.glsl"

#ifndef EIKON_STEP_STRUCTURE
#define EIKON_STEP_STRUCTURE 0
#endif
#ifndef EIKON_FRESNEL
#define EIKON_FRESNEL 1
#endif
#ifndef EIKON_HAS_ANISOTROPY
#define EIKON_HAS_ANISOTROPY 0
#endif
#ifndef EIKON_RECORD_EXIT
#define EIKON_RECORD_EXIT 0
#endif

#include "common/camera_block.glsl"

#include "common/environment.glsl"

#if EIKON_HAS_SCATTERING
layout(std430, binding = kFluence) readonly buffer Fluence { float fluence[]; };
layout(std430, binding = kFluenceDirection) readonly buffer FluenceDirection { float fluence_direction[]; };
#endif
#ifndef EIKON_MULTIPLE_SCATTERING
#define EIKON_MULTIPLE_SCATTERING 0
#endif
#if EIKON_MULTIPLE_SCATTERING
layout(std430, binding = kMultipleFluence) readonly buffer MultipleFluence { float multiple_fluence[]; };

// The lattice's fluence at x, trilinear between cell centres (the lattice
// is smooth on the scale of a cell, and a nearest-cell read shows the
// voxels in a coarse grid).
vec3 multiple_fluence_at(vec3 x) {
    vec3 u = (x - grid.bounds_min.xyz) / grid.voxel_size.xyz - 0.5f;
    ivec3 last = grid.resolution.xyz - 1;
    ivec3 low = clamp(ivec3(floor(u)), ivec3(0), last);
    vec3 t = clamp(u - vec3(low), vec3(0.0f), vec3(1.0f));
    vec3 sum = vec3(0.0f);
    for (int corner = 0; corner < 8; ++corner) {
        ivec3 bit = ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        ivec3 cell = min(low + bit, last);
        vec3 weight = mix(vec3(1.0f) - t, t, vec3(bit));
        uint index = 3u * uint(grid_linear_index(cell));
        sum += weight.x * weight.y * weight.z *
               vec3(multiple_fluence[index], multiple_fluence[index + 1u], multiple_fluence[index + 2u]);
    }
    return sum;
}
#endif
#if EIKON_HAS_ANISOTROPY
layout(binding = kAnisotropyTexture) uniform sampler3D anisotropy_texture;
#endif
#if EIKON_STEP_STRUCTURE
layout(binding = kStepTexture) uniform sampler3D step_structure;
#endif
layout(std430, binding = kHdrImage) buffer HdrImage { vec4 hdr_radiance[]; };
#if EIKON_RECORD_EXIT
layout(std430, binding = kViewExit) writeonly buffer ViewExit { vec4 view_exit[]; };  // xyz direction; w: 1 escaped, 2 receiver, 0 cut
#endif

uniform float step_length;   // m: step_voxels × the smallest voxel edge, the shortest step
uniform float longest_step;  // m: step_voxels × the largest voxel edge
uniform vec3 step_reach;     // m: step_voxels × the voxel's edge along each axis
uniform uint max_steps;
uniform float interface_half_width;  // m: beyond the smoothing kernel, where n is the bulk value
uniform uint pixel_stride;           // 1: a ray per pixel; k: a ray per k×k block (preview)
uniform vec2 sample_offset;          // where in its pixel the ray passes, as a fraction of the pixel (x right, y down)
uniform uint samples_before;         // passes already averaged into the image (0: this pass writes it)
uniform float footprint_pixels;      // the width of the pixel's share a ray stands for, in pixels

vec3 footprint_start;  // where the camera ray left the camera

// The environment seen from x along d, its checkerboard filtered over the ray's footprint there.
vec3 environment_seen(vec3 x, vec3 d) {
    float pixel = 2.0f * camera.position.w / float(camera.image.y);  // at unit distance, or m (orthographic)
    if (camera_is_orthographic()) {
        footprint_width = footprint_pixels * pixel;
    } else {
        footprint_growth = footprint_pixels * pixel;
        footprint_width = footprint_growth * distance(footprint_start, x);
    }
    return environment_radiance(x, d);
}

// σs·φ·p toward the camera (d: the ray's direction of travel). The radiance
// stored per voxel is its fluence φ and the power-weighted mean direction
// m of the photons through it (|m| ≤ 1); the phase function mixes
// isotropic and Henyey–Greenstein scattering about m by |m| ([Sun08]
// §4.4: the mean direction stands for the distribution). The material (σs,
// g) is read at `medium` (owned_medium_point), the fluences, which do not
// jump at a surface, at x.
vec3 in_scattered_radiance(vec3 x, vec3 medium, vec3 d, uint inside_mask) {
#if EIKON_HAS_SCATTERING
    uint index = 3u * uint(grid_linear_index(grid_cell(x)));
    vec3 phi = vec3(fluence[index], fluence[index + 1u], fluence[index + 2u]);
    float total = phi.r + phi.g + phi.b;
    vec3 direction_sum = vec3(fluence_direction[index], fluence_direction[index + 1u], fluence_direction[index + 2u]);
    float isotropic = 1.0f / (4.0f * 3.14159265358979f);
    float phase = isotropic;
    float coherence = total > 0.0f ? min(length(direction_sum) / total, 1.0f) : 0.0f;
    if (coherence > 0.0f) {
#if EIKON_HAS_ANISOTROPY
        float g = textureLod(anisotropy_texture, grid_uvw(medium), 0.0f).r;
#else
        float g = 0.0f;
#endif
        float cos_theta = dot(normalize(direction_sum), -d);
        phase = mix(isotropic, henyey_greenstein(cos_theta, g), coherence);
    }
#if EIKON_MULTIPLE_SCATTERING
    // Light scattered before, from the lattice: isotropic ([Bernabei12] §III-D).
    // Interpolated between cell centres, it is read a cell diagonal off a
    // sphere's or box's surface on the ray's side, where every centre read
    // lies on that side: an outer cell's, where the lattice's light streams
    // away, would darken the rim.
#if EIKON_SHARP_SURFACES
    vec3 lattice_point = off_sharp_surfaces(x, inside_mask, length(grid.voxel_size.xyz));
#else
    vec3 lattice_point = x;
#endif
    return sample_scattering(medium) * (phi * phase + multiple_fluence_at(lattice_point) * isotropic);
#else
    return sample_scattering(medium) * phi * phase;
#endif
#else
    return vec3(0.0f);
#endif
}

vec3 receiver_radiance(ReceiverHit hit) {
    if (!hit.lit_side) return vec3(0.0f);
    return receivers[hit.receiver].albedo.rgb / 3.14159265358979f * receiver_irradiance_at(hit.receiver, hit.map_uv);
}

// The step from x along d, where the field there is (∇n, n): step_voxels
// voxels along each axis (common/step_size.glsl), or, through a node of the
// step structure that is uniform in index and empty of extinction, to the
// node's face, at least that step and at most the node's cap or that step,
// whichever is longer.
float view_step(vec3 x, vec3 d, vec4 field) {
    vec3 bend = (field.xyz - dot(field.xyz, d) * d) / field.w;
    float ds = voxel_crossing_step(d, bend, step_reach, step_length, longest_step);
#if EIKON_STEP_STRUCTURE
    vec4 node = texelFetch(step_structure, grid_cell(x), 0);
    if (node.z > 0.5f && node.x > 0.0f)
        return octree_step(x, d, grid.bounds_min.xyz, grid.voxel_size.xyz, node.x, ds, max(node.y, ds));
#endif
    return ds;
}

// The share of an interface's reflection a step takes: a graded interface
// from n_lo to n_hi (sampled past the smoothing kernel on either side along
// ∇n) reflects R(θ, n_from, n_to) once in all; each step adds R times the
// fraction of the index jump it crosses. No term under total internal
// reflection: the ray equation turns the ray back itself.
float fresnel_share(vec3 start, vec3 end, vec3 d, float n_start, vec3 gradient, INOUT(vec3) normal) {
#if EIKON_FRESNEL
    float strength = length(gradient);
    // Over a voxel's smallest edge, the scale interface_half_width is measured in.
    if (strength * min(grid.voxel_size.x, min(grid.voxel_size.y, grid.voxel_size.z)) < 1e-4f) return 0.0f;
    normal = gradient / strength;
    float n_lo = reference_index() + sample_gradient_and_delta(start - interface_half_width * normal).w;
    float n_hi = reference_index() + sample_gradient_and_delta(start + interface_half_width * normal).w;
    float jump = n_hi - n_lo;
    if (jump < 1e-3f) return 0.0f;
    float cos_i = dot(d, normal);
    float reflectance = cos_i > 0.0f ? fresnel_reflectance(cos_i, n_lo, n_hi) : fresnel_reflectance(-cos_i, n_hi, n_lo);
    if (reflectance >= 1.0f) return 0.0f;
    float n_end = reference_index() + sample_gradient_and_delta(end).w;
    return reflectance * clamp(abs(n_end - n_start) / jump, 0.0f, 1.0f);
#else
    return 0.0f;
#endif
}

// One branch of a camera ray: where it is, where it goes (v = n·dx/ds), what
// fraction of the pixel's radiance it carries, the sharp surfaces it is
// inside and how many surface events it has met.
struct ViewRay {
    vec3 x;
    vec3 v;
    vec3 throughput;
    uint inside_mask;
    uint depth;
};

const int MAX_PENDING = 8;
ViewRay pending[MAX_PENDING];  // branches split off and not yet traced (depth first)
int pending_count = 0;

#if EIKON_SHARP_SURFACES
// Where a step ended at a sharp surface (`crossing`): the branch goes on refracted with
// (1 − R) of its throughput and, while it has met fewer than surface_depth
// events, the reflection with R is traced as well; past that it follows the
// stronger of the two. Total internal reflection keeps all of it.
void split_at_sharp_surface(SurfaceCrossing crossing, INOUT(ViewRay) ray) {
    vec3 d = normalize(ray.v);
    SurfaceEvent event = sharp_surface_event(crossing, ray.x, d, ray.inside_mask, 1.0f);
    float reflectance = event.reflectance;
    ++ray.depth;
    if (reflectance >= 1.0f) {
        ray.x = event.x_reflected;
        ray.v = event.n_here * mirrored_direction(d, event.facing);
        return;
    }
    ViewRay mirrored = ray;
    mirrored.x = event.x_reflected;
    mirrored.v = event.n_here * mirrored_direction(d, event.facing);
    ray.x = event.x_transmitted;
    mirrored.throughput = ray.throughput * reflectance;
    ray.v = event.n_beyond * refracted_direction(d, event.facing, event.n_here, event.n_beyond);
    ray.inside_mask = event.beyond_mask;
    ray.throughput *= 1.0f - reflectance;
    if (reflectance <= 0.0f) return;
    if (ray.depth <= surface_depth && pending_count < MAX_PENDING) {
        pending[pending_count++] = mirrored;
    } else if (reflectance > 0.5f) {
        mirrored.throughput = ray.throughput + mirrored.throughput;  // the stronger branch carries the whole
        ray = mirrored;
    } else {
        ray.throughput += mirrored.throughput;
    }
}
#endif

#include "common/pass_loops.glsl"

void main() {
    uvec2 block = gl_GlobalInvocationID.xy * pixel_stride;
    if (any(greaterThanEqual(block, camera.image.xy))) return;
    uvec2 pixel = min(block + pixel_stride / 2u, camera.image.xy - 1u);
    vec2 point = vec2(pixel) + sample_offset;
    vec3 direction = camera_ray_direction_at(point);
    ViewRay ray;
    ray.x = camera_ray_origin_at(point);
    footprint_start = ray.x;
    ray.inside_mask = 0u;
#if EIKON_SHARP_SURFACES
    if (grid_contains(ray.x)) ray.inside_mask = inside_mask_at(ray.x);
    sharp_offset = sharp_index_offset(ray.inside_mask);
#endif
    ray.v = (grid_contains(ray.x) ? field_at(ray.x).w : reference_index()) * direction;
    ray.throughput = vec3(1.0f);
    ray.depth = 0u;
    vec3 radiance = vec3(0.0f);
    uint steps = 0u;
    float exit_kind = 0.0f;
    vec3 exit_direction = direction;
    bool first_branch = true;  // the exit recorded for tests is that of the branch traced first

    for (;;) {
        vec3 x = ray.x;
        vec3 x_lost = vec3(0.0f);  // Kahan compensation of x
        vec3 v = ray.v;
        float branch_exit = 0.0f;
#if EIKON_SHARP_SURFACES
        // The first mesh facet along mesh_ahead_direction (zero: none
        // searched yet), searched from the point the ray has since travelled
        // mesh_ahead_travelled beyond.
        SurfaceCrossing mesh_ahead = no_surface_crossing(0.0f);
        vec3 mesh_ahead_direction = vec3(0.0f);
        float mesh_ahead_travelled = 0.0f;
#endif
        // The field (∇n, n) at x while `field_fresh`: the leapfrog leaves its
        // end sample there, which the next step starts from (one sample a
        // step); moving x otherwise (entering the grid, a sharp surface)
        // takes a new one.
        vec4 field = vec4(0.0f);
        bool field_fresh = false;
        bool stepped_out = false;  // x is where a step that left the grid ended, past its boundary
        for (;;) {
            // Where the driver caps loops, a ray out of budget keeps the
            // radiance it has gathered (docs/accuracy.md).
            spend_loops(loops_per_pass());
            if (!loops_left()) break;
            if (!grid_contains(x)) {
                vec3 d = normalize(v);
                StraightFlight flight = fly_straight(x, d);
                if (flight.hit.receiver >= 0) {
                    radiance += ray.throughput * receiver_radiance(flight.hit);
                    branch_exit = 2.0f;
                    break;
                }
                if (!flight.enters_grid) {
                    // Seen from where the ray crossed the grid's boundary: the
                    // step overshot it by up to its length, and a ground
                    // plane just below the grid's floor lies within that.
                    radiance += ray.throughput * environment_seen(stepped_out ? grid_exit_point(x, d) : x, d);
                    branch_exit = 1.0f;
                    break;
                }
                x = grid_entry_point(x, d, flight);
                x_lost = vec3(0.0f);
                field_fresh = false;
                stepped_out = false;
#if EIKON_SHARP_SURFACES
                mesh_ahead_direction = vec3(0.0f);
#endif
                if (grid_contains(x)) {
#if EIKON_SHARP_SURFACES
                    ray.inside_mask = inside_mask_at(x);
                    sharp_offset = sharp_index_offset(ray.inside_mask);
#endif
                    field = field_at(x);
                    field_fresh = true;
                    v = field.w * d;
                }
                continue;
            }
            if (steps >= max_steps) break;
            if (!field_fresh) field = field_at(x);
            field_fresh = true;
            float n_start = field.w;
            vec3 gradient = field.xyz;
            vec3 d = normalize(v);
            float ds = view_step(x, d, field);
#if EIKON_SHARP_SURFACES
            // Meshes are searched once per straight stretch: where the field
            // has no gradient the ray keeps its direction, and the first
            // facet ahead, found out to the grid's face, stays the first as
            // the ray advances (a search per step through a water surface's
            // tree cost 14 times the rest of the view pass).
            if (gradient != vec3(0.0f) || d != mesh_ahead_direction) {
                mesh_ahead = nearest_triangle_crossing(no_surface_crossing(max(grid_ray_interval(x, d).y, 0.0f)), x, d);
                mesh_ahead_direction = d;
                mesh_ahead_travelled = 0.0f;
            }
            SurfaceCrossing crossing = no_surface_crossing(ds);
            if (mesh_ahead.surface >= 0 && mesh_ahead.distance - mesh_ahead_travelled < ds) {
                crossing = mesh_ahead;
                crossing.distance = max(mesh_ahead.distance - mesh_ahead_travelled, 0.0f);
            }
            crossing = nearest_shape_crossing(crossing, x, d, ray.inside_mask, 1e-4f * grid.voxel_size.x);
            ds = crossing.distance;
            mesh_ahead_travelled += ds;
            if (!loops_left()) break;
#endif
            vec3 start = x;
            integrate_leapfrog(x, x_lost, v, field, ds);
            ++steps;
            ReceiverHit hit = first_receiver_crossing(start, x);
            float travelled = hit.receiver >= 0 ? hit.fraction * ds : ds;
#if EIKON_SHARP_SURFACES
            vec3 medium = owned_medium_point(start, ray.inside_mask);
#else
            vec3 medium = start;
#endif
            vec3 kappa = sample_extinction(medium);
            vec3 gathered = in_scattered_radiance(start, medium, d, ray.inside_mask) + sample_emission(medium);
            radiance += ray.throughput * gathered * attenuated_track_length(kappa, travelled);
            ray.throughput *= beer_lambert_transmittance(kappa, travelled);
            vec3 normal = vec3(0.0f);
            float reflection = fresnel_share(start, x, d, n_start, gradient, normal);
            if (reflection > 0.0f) {
                radiance += ray.throughput * reflection * environment_seen(start, reflect(d, normal));
                ray.throughput *= 1.0f - reflection;
            }
            if (hit.receiver >= 0) {
                radiance += ray.throughput * receiver_radiance(hit);
                branch_exit = 2.0f;
                v = d;
                break;
            }
#if EIKON_SHARP_SURFACES
            if (crossing.surface >= 0) {
                mesh_ahead_direction = vec3(0.0f);  // at normal incidence d stays as it was
                ray.x = x;
                ray.v = v;
                split_at_sharp_surface(crossing, ray);
                x = ray.x;
                x_lost = vec3(0.0f);
                v = ray.v;
                sharp_offset = sharp_index_offset(ray.inside_mask);
                field_fresh = false;
            }
#endif
            if (!grid_contains(x)) {
                v = reference_index() * normalize(v);
                stepped_out = true;
            }
        }
        if (first_branch) {
            exit_kind = branch_exit;
            exit_direction = normalize(v);
            first_branch = false;
        }
        if (pending_count == 0 || !loops_left()) break;
        ray = pending[--pending_count];
#if EIKON_SHARP_SURFACES
        sharp_offset = sharp_index_offset(ray.inside_mask);
#endif
    }
    uvec2 block_end = min(block + pixel_stride, camera.image.xy);
    if (samples_before > 0u) {
        uint i = pixel.y * camera.image.x + pixel.x;  // a pass of the full image: the block is the pixel
        vec3 mean = hdr_radiance[i].rgb;
        hdr_radiance[i] = vec4(mean + (radiance - mean) / float(samples_before + 1u), 1.0f);
    } else {
        for (uint y = block.y; y < block_end.y; ++y)
            for (uint x = block.x; x < block_end.x; ++x) hdr_radiance[y * camera.image.x + x] = vec4(radiance, 1.0f);
    }
#if EIKON_RECORD_EXIT
    if (samples_before == 0u) view_exit[pixel.y * camera.image.x + pixel.x] = vec4(exit_direction, exit_kind);
#endif
}
