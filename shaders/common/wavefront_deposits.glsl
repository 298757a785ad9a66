// The wavefront pass's deposits (wavefront_trace.comp): 64-bit fixed-point
// tallies of the energy balance and the receivers' texels, and a patch's
// power spread over its footprint by exact texel coverage
// (common/footprint_coverage.glsl). The includer declares `power_unit` and
// the tally blocks, and includes common/wide_units.glsl. Shared by GLSL and
// C++ (render/stages/NativeWavefrontTrace.cpp, where ADD_WIDE_UNITS adds to
// a thread's 64-bit sums).

void add_stat(int tally, vec3 watts) {
    for (int c = 0; c < 3; ++c)
        ADD_WIDE_UNITS(power_tallies, uint(2 * (3 * tally + c)), wide_units(watts[c] / power_unit[c]));
}

void deposit_in_texel(int r, ivec2 texel, vec3 watts) {
    uint resolution = receivers[r].map.y;
    uint base = 6u * (receivers[r].map.x + uint(texel.y) * resolution + uint(texel.x));
    for (int c = 0; c < 3; ++c)
        ADD_WIDE_UNITS(receiver_tallies, base + uint(2 * c), wide_units(watts[c] / power_unit[c]));
}

ivec2 texel_of(int r, vec2 map_uv) {
    int resolution = int(receivers[r].map.y);
    return clamp(ivec2(map_uv * float(resolution)), ivec2(0), ivec2(resolution - 1));
}

bool on_square(vec2 map_uv) { return all(greaterThanEqual(map_uv, vec2(0.0f))) && all(lessThan(map_uv, vec2(1.0f))); }

// Largest footprint, in texels of its bounding box on the map, spread by
// coverage; a larger one (only patches at the limit) is deposited at its
// corners.
const int kMaxFootprintTexels = 256;

// The patch's power `watts`, arriving in receiver r's plane over the
// triangle of map coordinates (a, b, c), into the texels of the square it
// covers by their share of its area; returns the share of `watts` that fell
// on the square (the rest passed its edge).
float deposit_footprint(int r, vec2 a, vec2 b, vec2 c, vec3 watts) {
    float resolution = float(receivers[r].map.y);
    vec2 ta = a * resolution;
    vec2 tb = b * resolution;
    vec2 tc = c * resolution;
    vec2 first = max(floor(min(ta, min(tb, tc))), vec2(0.0f));
    vec2 last = min(floor(max(ta, max(tb, tc))), vec2(resolution - 1.0f));
    if (any(greaterThan(first, last))) return 0.0f;  // wholly beside the square
    float area = 0.5f * abs(twice_signed_area(ta, tb, tc));
    ivec2 span = ivec2(last - first) + 1;
    if (area <= 1e-12f) {  // folded to a line or a point: at the centroid
        vec2 middle = (a + b + c) / 3.0f;
        if (!on_square(middle)) return 0.0f;
        deposit_in_texel(r, texel_of(r, middle), watts);
        return 1.0f;
    }
    if (span.x * span.y > kMaxFootprintTexels) {
        float share = 0.0f;
        vec2 corners[3];
        corners[0] = a;
        corners[1] = b;
        corners[2] = c;
        for (int k = 0; k < 3; ++k)
            if (on_square(corners[k])) {
                deposit_in_texel(r, texel_of(r, corners[k]), watts / 3.0f);
                share += 1.0f / 3.0f;
            }
        return share;
    }
    spend_loops(uint(span.x * span.y));
    ta -= first;  // coordinates from the first texel, for precision
    tb -= first;
    tc -= first;
    float covered_sum = 0.0f;
    for (int j = 0; j < span.y; ++j)
        for (int i = 0; i < span.x; ++i) {
            float covered = triangle_texel_coverage(ta, tb, tc, vec2(float(i), float(j)));
            if (covered <= 0.0f) continue;
            deposit_in_texel(r, ivec2(first) + ivec2(i, j), watts * (covered / area));
            covered_sum += covered;
        }
    return min(covered_sum / area, 1.0f);
}
