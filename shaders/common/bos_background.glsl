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
// Coordinates on the background in m along the camera's right and up from
// its axis. GLSL only.
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
