// The background of background-oriented schlieren (docs/scene-format.md,
// `diagnostic`, "bos"): seeded random dark dots on white, a random-dot
// pattern whose dots span a few pixels on the image ([Raffel15]). The
// plane is cut into square cells of side `dot_cell`, one dot a cell at a
// place drawn from (seed, cell) by the PCG hash; a dot darkens the white
// by exp(−8·r²/d²) at r from its centre (d = `dot_diameter`, its 1/e²
// diameter), overlapping dots multiply. Only the dots of the 3 × 3 cells
// about a point are summed: with the dot density π·d²/(4·cell²) ≤ 0.5
// (DiagnosticParser) a cell is at least 1.25·d wide, so any other dot is at
// least that far and darkens the point by less than e^−12.5 (4·10⁻⁶).
// Or (EIKON_BOS_IMAGE 1) an image file's luminance (Rec. 709 weights of
// its linear RGB, io/image/ImageIo's readSrgbImageAsLinear), its texels
// filtered bilinearly: the image `pattern_size` m wide and high, centred on
// the camera's axis, row 0 at the top, repeated across the plane.
// Coordinates on the background in m along the camera's right and up from
// its axis. GLSL only.
#ifndef EIKON_BOS_IMAGE
#define EIKON_BOS_IMAGE 0
#endif

#if EIKON_BOS_IMAGE
layout(binding = kBackgroundPatternTexture) uniform sampler2D pattern_texture;
uniform vec2 pattern_size;  // m

float background_intensity(vec2 q) {
    vec2 uv = vec2(q.x / pattern_size.x + 0.5f, 0.5f - q.y / pattern_size.y);
    return dot(textureLod(pattern_texture, uv, 0.0f).rgb, vec3(0.2126f, 0.7152f, 0.0722f));
}
#else
#include "common/random.glsl"

uniform uint dot_seed;
uniform float dot_cell;      // m
uniform float dot_diameter;  // m

float background_intensity(vec2 q) {
    vec2 cell = floor(q / dot_cell);
    float white = 1.0f;
    for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) {
            vec2 c = cell + vec2(float(i), float(j));
            uint index = pcg_hash(uint(int(c.x))) ^ pcg_hash(uint(int(c.y)) + 0x9e3779b9u);
            vec2 centre = (c + vec2(random_uniform(dot_seed, index, 0u), random_uniform(dot_seed, index, 1u))) * dot_cell;
            vec2 r = q - centre;
            white *= 1.0f - exp(-8.0f * dot(r, r) / (dot_diameter * dot_diameter));
        }
    return white;
}
#endif
