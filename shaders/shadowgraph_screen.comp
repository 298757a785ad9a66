// The shadowgraph's screen (docs/scene-format.md, `diagnostic`,
// "shadowgraph"): the light of diagnostic_rays.comp's corner rays, spread
// over the screen by the intensity law ([Settles01] ch. 6; as the
// wavefront pass spreads a patch's power, common/wavefront_deposits.glsl).
// The beam is `beam_margin` pixels wider than the picture on every side, so
// that light bent onto the picture from beside it is there (light bent
// farther is not). Each pixel's square of the parallel beam is cut into
// k × k squares (`beam_subdivision` k, render.samples_per_pixel = k²), each
// carrying its share I₀·T/k² of the pixel's power (T its corners' mean
// transmittance); its corner rays land on the screen at four points, and
// the square's two triangles (corners 00–10–11 and 00–11–01) each carry
// half of it onto the triangle their corners span there, at the
// irradiance of its power over its area — the piecewise-linear mapping's
// exact intensity law, 1/|det J| of the mapping, also where it folds (caustics: every sheet of it adds). The screen's
// pixels take each triangle's power by the share of its area over them
// (common/footprint_coverage.glsl), into 64-bit fixed-point tallies, so
// that each pixel holds its mean irradiance and the power is kept exactly.
// A square with a corner ray cut by the step cap, or lost (turned back by a
// sharp surface, diagnostic_rays.comp), carries nothing.
//
// EIKON_SCREEN_PASS 0: one invocation per square of the beam's k × k a pixel, deposits; 1: one per
// pixel, I/I₀ from the tallies into HdrImage and, exposed so that I₀ is
// mid-grey, LdrImage (row 0 at the top). Program options: EIKON_SCREEN_PASS, EIKON_HAS_EXTINCTION, EIKON_LOOP_BUDGET.
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/loop_budget.glsl"
#include "common/footprint_coverage.glsl"
#include "common/wide_units.glsl"
#include "common/camera_block.glsl"
#include "common/srgb.glsl"

// Per pixel and channel a 64-bit sum of units of I₀ · pixel area; one
// channel where the scene has no extinction (T = 1: the channels are equal).
layout(std430, binding = kDiagnosticScreen) coherent buffer DiagnosticScreen { uint tallies[]; };
#if EIKON_HAS_EXTINCTION
const int kChannels = 3;
#else
const int kChannels = 1;
#endif
// The channels tallied: 1 where the extinction is grey (T equal in all
// three), else kChannels.
uniform int tallied_channels;

const float kUnit = 1.0f / 16777216.0f;  // 2⁻²⁴ of a pixel's undisturbed power

#if EIKON_SCREEN_PASS == 0
// Per corner ray (landing right, up in pixels; 0; 0), (T rgb, how it ended).
layout(std430, binding = kDiagnosticLanding) readonly buffer DiagnosticLanding { vec4 landing[]; };

// Largest triangle, in pixels of its bounding box, spread by coverage; a
// larger one (light spread over hundreds of pixels, far below I₀) goes to
// its corners, a third each.
const int kMaxFootprintPixels = 256;

void deposit_in_pixel(ivec2 pixel, vec3 power) {
    uint base = uint(2 * kChannels) * (uint(pixel.y) * camera.image.x + uint(pixel.x));
    for (int c = 0; c < tallied_channels; ++c) ADD_WIDE_UNITS(tallies, base + uint(2 * c), wide_units(power[c] / kUnit));
}

bool on_screen(ivec2 pixel) { return all(greaterThanEqual(pixel, ivec2(0))) && all(lessThan(pixel, ivec2(camera.image.xy))); }

// `power` (in units of a pixel's undisturbed power) over the triangle
// (a, b, c), in pixel units from the top-left corner of pixel `origin`
// (x right, y down; small numbers, for precision), into the pixels it
// covers by their share of its area. The pixels spanned are those the
// triangle's bounding box overlaps with a width: a corner on a pixel's
// edge does not reach past it, so that undisturbed light — a square
// landing on its own pixel — fills one pixel, whose share is the whole.
void deposit_triangle(ivec2 origin, vec2 a, vec2 b, vec2 c, vec3 power) {
    ivec2 first = ivec2(floor(min(a, min(b, c))));
    ivec2 last = ivec2(ceil(max(a, max(b, c)))) - 1;
    ivec2 low = max(origin + first, ivec2(0));
    ivec2 high = min(origin + last, ivec2(camera.image.xy) - 1);
    if (any(greaterThan(low, high))) return;  // wholly off the screen
    float area = 0.5f * abs(twice_signed_area(a, b, c));
    ivec2 span = last - first + 1;
    if (area <= 1e-12f) {  // folded to a line or a point: at the centroid
        ivec2 middle = origin + ivec2(floor((a + b + c) / 3.0f));
        if (on_screen(middle)) deposit_in_pixel(middle, power);
        return;
    }
    if (span.x * span.y == 1) {  // within one pixel
        deposit_in_pixel(origin + first, power);
        return;
    }
    if (span.x * span.y > kMaxFootprintPixels) {
        vec2 corners[3] = vec2[3](a, b, c);
        for (int k = 0; k < 3; ++k) {
            ivec2 pixel = origin + ivec2(floor(corners[k]));
            if (on_screen(pixel)) deposit_in_pixel(pixel, power / 3.0f);
        }
        return;
    }
    spend_loops(uint((high.x - low.x + 1) * (high.y - low.y + 1)));
    vec2 shift = vec2(first);  // coordinates from the first pixel
    a -= shift;
    b -= shift;
    c -= shift;
    for (int j = low.y; j <= high.y; ++j)
        for (int i = low.x; i <= high.x; ++i) {
            ivec2 texel = ivec2(i, j) - origin - first;
            float covered = triangle_texel_coverage(a, b, c, vec2(texel));
            if (covered > 0.0f) deposit_in_pixel(ivec2(i, j), power * (covered / area));
        }
}

uniform uint beam_margin;       // pixels of the beam beside the picture on every side
uniform uint beam_subdivision;  // k: each pixel's square of the beam cut into k × k

void main() {
    uvec2 square = gl_GlobalInvocationID.xy;
    uvec2 squares = beam_subdivision * (camera.image.xy + 2u * beam_margin);
    if (any(greaterThanEqual(square, squares))) return;
    uint stride = squares.x + 1u;
    uint corners[4] = uint[4](square.y * stride + square.x, square.y * stride + square.x + 1u,
                              (square.y + 1u) * stride + square.x, (square.y + 1u) * stride + square.x + 1u);
    vec2 within = vec2(square % beam_subdivision);  // the square's place in its pixel's k × k
    float side = 1.0f / float(beam_subdivision);
    vec2 lands[4];
    vec3 transmittance = vec3(0.0f);
    for (int k = 0; k < 4; ++k) {
        vec4 moved = landing[2u * corners[k]];
        vec4 light = landing[2u * corners[k] + 1u];
        // Cut by the step cap (0), where its light went is not known; or lost
        // (3), turned back before the screen: the square carries nothing.
        if (light.w == 0.0f || light.w == 3.0f) return;
        // From the square's own pixel's top-left corner; the image's up is the pixels' −y.
        lands[k] = (within + vec2(float(k & 1), float(k >> 1))) * side + vec2(moved.x, -moved.y);
        transmittance += 0.25f * light.xyz;
    }
    ivec2 origin = ivec2(square / beam_subdivision) - int(beam_margin);
    vec3 power = side * side * transmittance;  // the square's share of its pixel's I₀·T
    // A square that lands within one pixel (undisturbed light, most of the
    // screen) gives it all its power, as its two triangles would, in one
    // deposit instead of two.
    ivec2 first = ivec2(floor(min(min(lands[0], lands[1]), min(lands[2], lands[3]))));
    ivec2 last = ivec2(ceil(max(max(lands[0], lands[1]), max(lands[2], lands[3])))) - 1;
    if (first == last) {
        if (on_screen(origin + first)) deposit_in_pixel(origin + first, power);
        return;
    }
    deposit_triangle(origin, lands[0], lands[1], lands[3], 0.5f * power);
    deposit_triangle(origin, lands[0], lands[3], lands[2], 0.5f * power);
}
#else
layout(std430, binding = kHdrImage) writeonly buffer HdrImage { vec4 hdr_radiance[]; };
layout(std430, binding = kLdrImage) writeonly buffer LdrImage { uint ldr_rgba8[]; };

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, camera.image.xy))) return;
    uint i = pixel.y * camera.image.x + pixel.x;
    vec3 intensity;
    uint base = uint(2 * kChannels) * i;
    for (int c = 0; c < tallied_channels; ++c)
        intensity[c] = (float(tallies[base + uint(2 * c) + 1u]) * 4294967296.0f + float(tallies[base + uint(2 * c)])) * kUnit;
    if (tallied_channels == 1) intensity = vec3(intensity.x);
    hdr_radiance[i] = vec4(intensity, 1.0f);
    // Exposed so that the undisturbed screen is mid-grey, twice its irradiance white.
    ldr_rgba8[i] = packUnorm4x8(vec4(srgb_encode(0.5f * intensity), 1.0f));
}
#endif
