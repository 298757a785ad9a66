// Diagnostics (docs/scene-format.md, `diagnostic`): light through the
// test volume, one ray per pixel along the camera's rays — parallel ones
// from the orthographic camera's image plane, or from a perspective
// camera's pinhole for background-oriented schlieren — marched through the
// graded field by the camera rays' leapfrog (common/integrators.glsl;
// view_rays.comp) with fixed steps of `step_length`, the last one cut at the
// grid's far face — or, as the error estimate's reference march
// (render/stages/DiagnosticErrorEstimate.h), by RK4. Along the way it sums
// the optical path difference OPD = ∫ (n − n_ref) ds by the trapezoid rule
// over each step (second order, as the leapfrog is); where it leaves the
// grid (the medium is uniform beyond) its deflection ε is the change of its
// unit direction on its frame's right and up axes. Where the scene has
// extinction it also sums the optical depth ∫κ ds, by the same rule. The
// instrument (common/diagnostic_instruments.glsl) turns (OPD, ε, the
// transmittance) into the ray's I/I₀.
//
// Shadowgraph and BOS follow each ray on, straight, from where it leaves the
// grid to a plane across the camera's axis `plane_depth` from the camera
// (the screen, the background): where it lands there, relative to where the
// straight ray would, in pixels on the image's right and up axes.
//
// The ray is marched in its own frame (x right, y up, z along its first
// direction: for parallel light the camera's frame), the field's gradient
// turned into it, so that ε — parts in 1e4 of a unit vector — is carried in
// float32 with its own precision rather than as the difference of two world
// directions near 1; and OPD sums δn as the field holds it, since
// n_ref + δn in float32 rounds δn.
//
// Sharp surfaces (common/sharp_surface_crossings.glsl, as the camera's view
// rays and the photons cross them): a step that would cross one ends
// exactly on it, and the ray goes on refracted (Snell), its transmittance
// times Fresnel's 1 − R (the reflected share leaves the beam), or mirrored
// where it is totally reflected; inside an object δn is the graded field's
// plus the object's offset, so OPD = ∫ (n − n_ref) ds takes in the glass
// along the ray's actual path. Through glass ε is no longer small: it is
// the angle θ between the exit direction and the ray's first direction,
// along the direction in which the exit direction's part across the beam
// points. A ray that leaves turned back (at 90° or more from the camera's
// axis: it never reaches the instrument's optics, the screen or the camera)
// is lost: its ray is dark in every instrument and lands nowhere.
//
// A preview (`pixel_stride` k > 1, the viewer while the camera moves)
// traces one ray per k×k block of pixels, through the middle of the pixel
// nearest the block's centre, and fills the block with it, as the view's
// preview does (view_rays.comp); the shadowgraph has none.
// A pass traces one ray a pixel, through the point `sample_offset` of it
// (render/stages/PixelSamples.h: render.samples_per_pixel = k² passes
// through the centres of a k × k grid of cells, as the view's); each
// measurement is the running mean of the `samples_before` passes before it
// and this one — a box filter over the pixel, for the picture and for the
// measured quantities alike. Writes per pixel (ε_right, ε_up, OPD, how its
// rays ended: 1 crossed the grid, 2 all missed it, 0 one was cut by the
// step cap or the loop budget, 3 one was lost, which outranks the others).
// Every instrument but the shadowgraph writes the linear I/I₀ (HdrImage)
// and its sRGB encoding (LdrImage), row 0 at the top; BOS also writes the
// background without the medium (DiagnosticReference) and per pixel its
// displacement (DiagnosticLanding).
// The shadowgraph's rays start at the corners of a beam `beam_margin`
// pixels wider than the picture on every side, each pixel's square of it
// cut into k × k squares (`beam_subdivision` k), so
// (k·(width + 2·margin) + 1) × (k·(height + 2·margin) + 1) of them, and
// write where they land and their transmittance (DiagnosticLanding) for
// shadowgraph_screen.comp.
// Inside the varying box the leapfrog steps across nodes where the medium is
// nearly uniform (render/stages/DiagnosticNodeSteps.h) to the node's far
// face, in whole steps of `step_length`, as the view steps across its
// octree's nodes (view_rays.comp, common/step_size.glsl); RK4 keeps uniform
// steps, so that the error estimate's reference measures what they cost.
// Program options: EIKON_INSTRUMENT, EIKON_HAS_EXTINCTION, EIKON_LOOP_BUDGET,
// EIKON_INTEGRATOR (1 leapfrog, 2 RK4, as common/ray_march.glsl numbers them),
// EIKON_NODE_STEPS (1: the steps across nodes; EIKON_BRICK_VOXELS voxels a
// brick of their levels, render/stages/VaryingVoxels.h BrickRanges),
// EIKON_BOS_IMAGE (1: BOS's background is an image, common/bos_background.glsl),
// EIKON_SHARP_SURFACES (0 none, 1 spheres and boxes, 2 meshes or water too;
// render/stages/SharpSurfaceBuffer, kindsOption).
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/grid_sampling.glsl"
#include "common/loop_budget.glsl"
#include "common/ray_step.glsl"
#include "common/camera_block.glsl"
#include "common/srgb.glsl"
#include "common/diagnostic_instruments.glsl"

#ifndef EIKON_SHARP_SURFACES
#define EIKON_SHARP_SURFACES 0
#endif
#if EIKON_SHARP_SURFACES
#include "common/fresnel.glsl"
#include "common/sharp_surfaces.glsl"
#include "common/sharp_surface_blocks.glsl"
uint inside_mask = 0u;        // the sharp surfaces the ray is inside
float sharp_offset = 0.0f;    // δn the sharp objects it is inside add to the graded field
#endif

vec3 ray_origin;      // world position of the ray's frame's origin, where it entered the grid
vec3 ray_right;       // the frame's axes: its first direction, and the image's right and up made square to it
vec3 ray_up;
vec3 ray_forward;
float sampled_delta;  // δn at field_at's latest point

vec3 world_direction(vec3 local) {
    return local.x * ray_right + local.y * ray_up + local.z * ray_forward;
}

vec3 local_direction(vec3 world) { return vec3(dot(world, ray_right), dot(world, ray_up), dot(world, ray_forward)); }

// (∇n, n) at a point of the ray's frame, the gradient on the frame's axes.
vec4 field_at(vec3 local) {
    vec4 sample_ = sample_gradient_and_delta(ray_origin + world_direction(local));
#if EIKON_SHARP_SURFACES
    sampled_delta = sample_.w + sharp_offset;
#else
    sampled_delta = sample_.w;
#endif
    vec3 gradient = sample_.xyz;
    return vec4(dot(gradient, ray_right), dot(gradient, ray_up), dot(gradient, ray_forward),
                reference_index() + sampled_delta);
}

#include "common/integrators.glsl"

#ifndef EIKON_INTEGRATOR
#define EIKON_INTEGRATOR 1
#endif

layout(std430, binding = kDiagnosticRays) buffer DiagnosticRays { vec4 rays[]; };
#if EIKON_INSTRUMENT >= EIKON_SHADOWGRAPH
// Shadowgraph: per corner ray (landing right, up in pixels; 0; 0), (T rgb, how it ended).
// BOS: per pixel (displacement right, up in pixels; the background's
// intensity without the medium; 0) and nothing.
layout(std430, binding = kDiagnosticLanding) buffer DiagnosticLanding { vec4 landing[]; };
uniform float plane_depth;  // m from the camera (its pinhole or image plane) along its axis
#endif
#if EIKON_INSTRUMENT != EIKON_SHADOWGRAPH
layout(std430, binding = kHdrImage) buffer HdrImage { vec4 hdr_radiance[]; };
layout(std430, binding = kLdrImage) writeonly buffer LdrImage { uint ldr_rgba8[]; };
uniform vec2 sample_offset;   // where in its pixel the ray passes, as a fraction of the pixel (x right, y down)
uniform uint samples_before;  // passes already averaged into the measurements (0: this pass writes them)

// A pixel's mean of `samples_before` rays' `mean` and this ray's `value`.
vec4 running_mean(vec4 mean, vec4 value) {
    return samples_before == 0u ? value : mean + (value - mean) / float(samples_before + 1u);
}
#endif
#if EIKON_INSTRUMENT == EIKON_BOS
layout(std430, binding = kDiagnosticReference) writeonly buffer DiagnosticReference { uint reference_rgba8[]; };
#endif

uniform float step_length;
uniform uint max_steps;

const float kRayCut = 0.0f;
const float kRayCrossed = 1.0f;
const float kRayMissed = 2.0f;
const float kRayLost = 3.0f;

struct Measured {
    float opd;
    vec3 optical_depth;
    vec2 deflection;
    float ended;
    vec2 landing;  // on the plane, m along the camera's right and up from the straight ray's point
    float fresnel_transmittance;  // the product of 1 − R over the sharp surfaces it was refracted through
};

#if EIKON_SHARP_SURFACES
// Where a step ended on a sharp surface (`crossing`): the ray, at x with v
// (its frame), goes on refracted into the side beyond, or mirrored where it
// is totally reflected; the refracted ray keeps 1 − R of the light.
void cross_sharp_surface(SurfaceCrossing crossing, INOUT(vec3) x, INOUT(vec3) v, INOUT(float) transmitted) {
    vec3 d = world_direction(normalize(v));
    SurfaceEvent event = sharp_surface_event(crossing, ray_origin + world_direction(x), d, inside_mask, 1.0f);
    vec3 at;
    if (event.reflectance >= 1.0f) {
        at = event.x_reflected;
        v = local_direction(event.n_here * mirrored_direction(d, event.facing));
    } else {
        at = event.x_transmitted;
        v = local_direction(event.n_beyond * refracted_direction(d, event.facing, event.n_here, event.n_beyond));
        inside_mask = event.beyond_mask;
        sharp_offset = event.beyond_offset;
        transmitted *= 1.0f - event.reflectance;
    }
    x = local_direction(at - ray_origin);
}
#endif

#if EIKON_SHARP_SURFACES
// How far a ray at p can go, along any path, before it can meet a sharp
// surface: the distance to the nearest sphere's or box's surface, or to a
// mesh's bounding box (0 inside it). A path is no shorter than the distance
// between its ends, so, bent or straight, the ray needs no search for the
// surfaces until it has travelled that far.
float surface_clearance(vec3 p) {
    float clearance = EIKON_NO_CROSSING;
    for (uint k = 0u; k < sharp_surface_count; ++k) {
        vec4 shape_a = sharp_surfaces[k].shape_a;
        vec4 shape_b = sharp_surfaces[k].shape_b;
        if (is_triangle_surface(k)) {
            int root = triangle_root(shape_b);
            vec3 outside = max(max(surface_nodes[2 * root].xyz - p, p - surface_nodes[2 * root + 1].xyz), vec3(0.0f));
            clearance = min(clearance, length(outside));
        } else if (is_box(shape_a)) {
            vec3 outside = max(max(shape_a.xyz - p, p - shape_b.xyz), vec3(0.0f));
            vec3 within = min(p - shape_a.xyz, shape_b.xyz - p);
            float inside = max(min(min(within.x, within.y), within.z), 0.0f);
            clearance = min(clearance, any(greaterThan(outside, vec3(0.0f))) ? length(outside) : inside);
        } else {
            clearance = min(clearance, abs(length(p - shape_a.xyz) - shape_b.x));
        }
    }
    return clearance;
}
#endif

// The deflection ε of a ray that left along v (its frame), on the frame's right and up axes.
vec2 deflection_of(vec3 v) {
    vec3 d = normalize(v);
#if EIKON_SHARP_SURFACES
    // The angle θ = atan2(|d⊥|, d_z) along d⊥/|d⊥|.
    float across = length(d.xy);
    return across > 0.0f ? (atan(across, d.z) / across) * d.xy : vec2(0.0f);
#else
    // In a graded field ε is small: sin θ, which is θ within θ²/6 (2e-7 at 1 mrad).
    return d.xy;
#endif
}

// Where the ray, leaving the grid at x with direction v (its frame),
// reaches the plane `plane_depth` from the camera, less where the straight
// ray (0, 0, s) reaches it: both in the plane, so the difference is square
// to the camera's axis, its part along the ray's axis found from the other
// two without cancelling.
vec2 landing_offset(vec3 x, vec3 v) {
#if EIKON_INSTRUMENT >= EIKON_SHADOWGRAPH
    vec3 axis = vec3(dot(camera.forward.xyz, ray_right), dot(camera.forward.xyz, ray_up),
                     dot(camera.forward.xyz, ray_forward));
    float depth = plane_depth - dot(ray_origin - camera.position.xyz, camera.forward.xyz);
    vec3 direction = normalize(v);
    float t = (depth - dot(x, axis)) / dot(direction, axis);
    vec2 across = x.xy + t * direction.xy;
    vec3 offset = world_direction(vec3(across, -(across.x * axis.x + across.y * axis.y) / axis.z));
    return vec2(dot(offset, camera.right.xyz), dot(offset, camera.up.xyz));
#else
    return vec2(0.0f);
#endif
}

// The box, in world coordinates, outside which the traced medium is
// uniform (render/stages/VaryingVoxels.h; the whole grid where unknown), and
// the δn and κ it holds there.
uniform vec3 varying_low;
uniform vec3 varying_high;
uniform float uniform_delta;
uniform vec3 uniform_extinction;

bool varying_contains(vec3 x) {
    return all(greaterThanEqual(x, varying_low)) && all(lessThanEqual(x, varying_high));
}

// Parameters (t_enter, t_leave) of the line x + t·d inside the varying box
// (slabs; a zero component of d becomes tiny so that 0·∞ never appears);
// t_enter > t_leave when it misses.
vec2 varying_ray_interval(vec3 x, vec3 d) {
    vec3 safe = mix(d, vec3(1e-12f), lessThan(abs(d), vec3(1e-12f)));
    vec3 t1 = (varying_low - x) / safe;
    vec3 t2 = (varying_high - x) / safe;
    vec3 t_low = min(t1, t2);
    vec3 t_high = max(t1, t2);
    return vec2(max(t_low.x, max(t_low.y, t_low.z)), min(t_high.x, min(t_high.y, t_high.z)));
}

#ifndef EIKON_NODE_STEPS
#define EIKON_NODE_STEPS 0
#endif
#if EIKON_NODE_STEPS
#include "common/step_size.glsl"
uniform uint node_steps;  // 0: no levels known, uniform steps
// Per brick of EIKON_BRICK_VOXELS³ voxels, the octree level of the nearly
// uniform node around it (its edge 2^level voxels), 0 for none.
layout(binding = kStepTexture) uniform sampler3D node_levels;
#endif

// The step from `position` (world), the ray's direction v (its frame):
// one `step_length`, or in a nearly uniform node as many whole ones as
// stay within it (at least one).
float march_step(vec3 position, vec3 v) {
#if EIKON_NODE_STEPS
    if (node_steps != 0u) {
        float level = texelFetch(node_levels, grid_cell(position) / EIKON_BRICK_VOXELS, 0).r;
        if (level > 0.0f) {
            float to_face = octree_step(position, world_direction(normalize(v)), grid.bounds_min.xyz,
                                        grid.voxel_size.xyz, level, step_length, 1e30f);
            return step_length * floor(to_face / step_length);
        }
    }
#endif
    return step_length;
}

// The ray from `start` along `direction`, marched through the grid. Where
// the medium is uniform — before the ray reaches the varying box and after
// it has left it — its gradient is 0 and the march is a straight line
// gathering δn and κ at a constant rate: the ray jumps there, by whole
// steps before the box (its steps inside fall where the march from the
// grid's face puts them) and to the grid's far face after it.
Measured march(vec3 start, vec3 direction) {
    ray_forward = direction;
    ray_right = normalize(cross(direction, camera.up.xyz));
    ray_up = cross(ray_right, direction);
    vec2 span = grid_ray_interval(start, direction);
    Measured measured;
    measured.opd = 0.0f;
    measured.optical_depth = vec3(0.0f);
    measured.deflection = vec2(0.0f);
    measured.ended = kRayMissed;
    measured.landing = vec2(0.0f);
    measured.fresnel_transmittance = 1.0f;
    float opd = 0.0f;
    vec3 optical_depth = vec3(0.0f);
    if (span.x < span.y && span.y > 0.0f) {
        float ended = kRayCut;
        ray_origin = start + max(span.x, 0.0f) * direction;
        vec3 x = vec3(0.0f);
        vec3 x_lost = vec3(0.0f);  // Kahan compensation of x
#if EIKON_SHARP_SURFACES
        inside_mask = inside_mask_at(ray_origin);
        sharp_offset = sharp_index_offset(inside_mask);
#endif
        vec4 field = field_at(x);
        vec3 v = vec3(0.0f, 0.0f, field.w);
        // The straight ray's way through the grid. A bent ray needs at least
        // as long to reach the far face, so the face is looked for along the
        // ray's own direction only over its last two steps (a slab test each
        // step cost a fifth of the pass); one that leaves by another face
        // first ends where its step took it out.
        float chord = span.y - max(span.x, 0.0f);
        float travelled = 0.0f;
        uint steps = 0u;
        bool varies = all(lessThanEqual(varying_low, varying_high));  // else the medium is uniform
        vec2 medium_span = varying_ray_interval(ray_origin, direction);
        if (!(varies && medium_span.x < medium_span.y && medium_span.y > 0.0f && medium_span.x < chord)) {
            // Straight across the grid, as the march would go with ∇n = 0.
            measured.opd = uniform_delta * chord;
            measured.optical_depth = uniform_extinction * chord;
            measured.ended = chord > float(max_steps) * step_length ? kRayCut : kRayCrossed;
            if (measured.ended == kRayCrossed) measured.landing = landing_offset(vec3(0.0f, 0.0f, chord), v);
            return measured;
        }
        if (medium_span.x > step_length) {
            steps = min(uint(medium_span.x / step_length), max_steps);
            travelled = float(steps) * step_length;
            x = vec3(0.0f, 0.0f, travelled);
            field = field_at(x);
            opd = uniform_delta * travelled;
            optical_depth = uniform_extinction * travelled;
        }
        float delta_before = sampled_delta;
#if EIKON_HAS_EXTINCTION
        vec3 kappa_before = sample_extinction(ray_origin + world_direction(x));
#endif
        float exit_tolerance = 1e-3f * min(min(grid.voxel_size.x, grid.voxel_size.y), grid.voxel_size.z);
        bool entered = false;  // the march has reached the varying box
#if EIKON_SHARP_SURFACES
        // How far the ray may still go without a search for the surfaces
        // (surface_clearance, less a margin for float32): the search runs only
        // near a surface (inside an object, every step).
        float clear = 0.0f;
        float clearance_margin = 1e-3f * grid.voxel_size.x;
#endif
        vec3 position = ray_origin + world_direction(x);
        for (; steps < max_steps; ++steps) {
            spend_loops(1u);
            if (!loops_left()) break;
            float ds = march_step(position, v);
            if (travelled + ds + step_length >= chord) {
                // NaN (a ray along a face) counts as out.
                float remaining = grid_ray_interval(ray_origin + world_direction(x), world_direction(normalize(v))).y;
                if (!(remaining > exit_tolerance)) {
                    ended = kRayCrossed;
                    break;
                }
                ds = min(ds, remaining);
            }
#if EIKON_SHARP_SURFACES
            SurfaceCrossing crossing = no_surface_crossing(ds);
            if (clear < ds) {
                vec3 here = ray_origin + world_direction(x);
                clear = surface_clearance(here) - clearance_margin;
                if (clear < ds)
                    crossing = nearest_surface_crossing(here, world_direction(normalize(v)), inside_mask, ds,
                                                        1e-4f * grid.voxel_size.x);
            }
            ds = crossing.distance;
            clear -= ds;
#endif
#if EIKON_INTEGRATOR == 2
            integrate_rk4(x, x_lost, v, field, ds);  // its last sample is at the new x, as the trapezoid needs
#else
            integrate_leapfrog(x, x_lost, v, field, ds);
#endif
            travelled += ds;
            opd += 0.5f * (delta_before + sampled_delta) * ds;
            delta_before = sampled_delta;
            position = ray_origin + world_direction(x);
#if EIKON_HAS_EXTINCTION
            vec3 kappa = sample_extinction(position);
            optical_depth += 0.5f * (kappa_before + kappa) * ds;
            kappa_before = kappa;
#endif
#if EIKON_SHARP_SURFACES
            if (crossing.surface >= 0) {
                cross_sharp_surface(crossing, x, v, measured.fresnel_transmittance);
                clear = 0.0f;
                x_lost = vec3(0.0f);
                field = field_at(x);
                delta_before = sampled_delta;
                position = ray_origin + world_direction(x);
            }
#endif
            if (varying_contains(position)) {
                entered = true;
            } else if (!grid_contains(position)) {
                ended = kRayCrossed;
                break;
            } else if (entered) {
                // Past the box: straight on to the grid's far face.
                vec3 heading = normalize(v);
                float remaining = max(grid_ray_interval(position, world_direction(heading)).y, 0.0f);
                x += remaining * heading;
                opd += uniform_delta * remaining;
                optical_depth += uniform_extinction * remaining;
                ended = float(steps + 1u) + remaining / step_length > float(max_steps) ? kRayCut : kRayCrossed;
                break;
            }
        }
        measured.opd = opd;
        measured.optical_depth = optical_depth;
        measured.deflection = deflection_of(v);
#if EIKON_SHARP_SURFACES
        if (ended == kRayCrossed && dot(world_direction(v), camera.forward.xyz) <= 0.0f) ended = kRayLost;
#endif
        measured.ended = ended;
        if (ended == kRayCrossed) measured.landing = landing_offset(x, v);
    }
    return measured;
}

// The image plane's size of a pixel: m (orthographic), or at unit distance from the pinhole.
float pixel_size() { return 2.0f * camera.position.w / float(camera.image.y); }

#if EIKON_INSTRUMENT == EIKON_SHADOWGRAPH
uniform uint beam_margin;       // pixels of the beam beside the picture on every side
uniform uint beam_subdivision;  // k: each pixel's square of the beam cut into k × k

// One ray per corner of the beam's squares, (k·(width + 2·margin) + 1) × (k·(height + 2·margin) + 1).
void main() {
    uvec2 corner = gl_GlobalInvocationID.xy;
    uvec2 corners = beam_subdivision * (camera.image.xy + 2u * beam_margin);
    if (any(greaterThan(corner, corners))) return;
    vec2 point = vec2(corner) / float(beam_subdivision) - float(beam_margin);  // pixels from the picture's corner
    Measured measured = march(camera_ray_origin_at(point), camera.forward.xyz);
    uint i = corner.y * (corners.x + 1u) + corner.x;
    rays[i] = vec4(measured.deflection, measured.opd, measured.ended);
    landing[2u * i] = vec4(measured.landing / pixel_size(), 0.0f, 0.0f);
    landing[2u * i + 1u] = vec4(measured.fresnel_transmittance * exp(-measured.optical_depth), measured.ended);
}
#else
uniform uint pixel_stride;  // 1: a ray a pixel; k: a ray per k×k block of pixels, filling it (a preview)

void main() {
    uvec2 block = gl_GlobalInvocationID.xy * pixel_stride;
    if (any(greaterThanEqual(block, camera.image.xy))) return;
    uvec2 pixel = min(block + pixel_stride / 2u, camera.image.xy - 1u);  // the block's middle pixel
    vec2 point = vec2(pixel) + sample_offset;
    Measured measured = march(camera_ray_origin_at(point), camera_ray_direction_at(point));
    uint i = pixel.y * camera.image.x + pixel.x;
    // One lost ray marks its pixel lost; else one cut ray, cut; else one that crossed, crossed (0 < 1 < 2).
    float ended = measured.ended;
    if (samples_before > 0u) ended = max(rays[i].w, ended) == kRayLost ? kRayLost : min(rays[i].w, ended);
    vec4 ray = vec4(running_mean(rays[i], vec4(measured.deflection, measured.opd, 0.0f)).xyz, ended);
    // A lost ray brings no light.
    vec3 transmittance = measured.ended == kRayLost ? vec3(0.0f)
                                                    : measured.fresnel_transmittance * exp(-measured.optical_depth);
#if EIKON_INSTRUMENT == EIKON_BOS
    // The background point this ray sees without the medium, and with it.
    vec3 offset = camera_image_offset_at(point);
    vec2 straight = plane_depth * vec2(dot(offset, camera.right.xyz), dot(offset, camera.up.xyz));
    float unmoved = background_intensity(straight);
    // A ray that crossed no varying medium lands where the straight one does.
    float seen = all(equal(measured.landing, vec2(0.0f))) ? unmoved : background_intensity(straight + measured.landing);
    vec3 intensity = transmittance * seen;
    // The feature seen here with the medium is, without it, seen where its
    // straight ray points: the apparent displacement, reference to measurement.
    vec4 moved = running_mean(landing[i], vec4(-measured.landing / (plane_depth * pixel_size()), unmoved, 0.0f));
    uint reference = packUnorm4x8(vec4(srgb_encode(vec3(moved.z)), 1.0f));
#else
    float u = point.x / float(camera.image.x);
    vec3 intensity = instrument_intensity(measured.opd, measured.deflection, u, transmittance);
#endif
    vec3 mean = running_mean(hdr_radiance[i], vec4(intensity, 1.0f)).rgb;
    uint encoded = packUnorm4x8(vec4(srgb_encode(mean), 1.0f));
    // A pass of the full picture: the block is the pixel.
    uvec2 block_end = min(block + pixel_stride, camera.image.xy);
    for (uint y = block.y; y < block_end.y; ++y)
        for (uint x = block.x; x < block_end.x; ++x) {
            uint j = y * camera.image.x + x;
            rays[j] = ray;
#if EIKON_INSTRUMENT == EIKON_BOS
            landing[j] = moved;
            reference_rgba8[j] = reference;
#endif
            hdr_radiance[j] = vec4(mean, 1.0f);
            ldr_rgba8[j] = encoded;
        }
}
#endif
