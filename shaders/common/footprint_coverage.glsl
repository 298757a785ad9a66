// Exact coverage of a texel by a wavefront patch's footprint (the triangle
// its three corner rays span on a receiver), for the intensity-law deposit of
// the wavefront pass ([Ihrke07] §4.2: irradiance is a patch's power over its
// area): the area of triangle ∩ square by Green's theorem, as the signed sum
// over the triangle's edges of the area between each edge — clipped to the
// square's columns and clamped to its rows — and the square's bottom. No
// clipping polygon, so no arrays: a handful of scalar operations an edge.
// Texel coordinates: texel (i, j) is the square [i, i+1] × [j, j+1].
// Shared by GLSL and C++ (cpp_shim.h).

// Twice the signed area of the triangle (a, b, c).
float twice_signed_area(vec2 a, vec2 b, vec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
}

// ∫ clamp(t, 0, 1) dt.
float clamped_ramp_antiderivative(float t) {
    if (t <= 0.0f) return 0.0f;
    if (t >= 1.0f) return t - 0.5f;
    return 0.5f * t * t;
}

// The mean of clamp(y, 0, 1) as y runs linearly from y0 to y1; the
// difference of antiderivatives only where the ramp crosses 0 or 1 (inside
// the band it would cancel catastrophically for a nearly level edge).
float clamped_ramp_mean(float y0, float y1) {
    float low = min(y0, y1);
    float high = max(y0, y1);
    if (high <= 0.0f) return 0.0f;
    if (low >= 1.0f) return 1.0f;
    if (low >= 0.0f && high <= 1.0f) return 0.5f * (y0 + y1);
    if (high - low < 1e-6f) return clamp(0.5f * (y0 + y1), 0.0f, 1.0f);
    return (clamped_ramp_antiderivative(high) - clamped_ramp_antiderivative(low)) / (high - low);
}

// ∫ (clamp(y(x) − low.y, 0, 1) − level) dx along the edge p → q over the
// part of it above the columns [low.x, low.x + 1], signed by the edge's
// direction in x. Over a closed loop the constant `level` integrates to 0;
// taken near the triangle, it keeps a small triangle's terms small, so that
// they do not cancel to its area from much larger values.
float edge_band_integral(vec2 p, vec2 q, vec2 low, float level) {
    if (p.x == q.x) return 0.0f;
    bool rightward = q.x > p.x;
    vec2 left = rightward ? p : q;
    vec2 right = rightward ? q : p;
    float x0 = max(left.x, low.x);
    float x1 = min(right.x, low.x + 1.0f);
    if (x1 <= x0) return 0.0f;
    float slope = (right.y - left.y) / (right.x - left.x);
    float y0 = left.y + slope * (x0 - left.x) - low.y;
    float y1 = left.y + slope * (x1 - left.x) - low.y;
    float band = (x1 - x0) * (clamped_ramp_mean(y0, y1) - level);
    return rightward ? band : -band;
}

// Area of the part of triangle (a, b, c) — either orientation — inside the
// square [low, low + 1]².
float triangle_texel_coverage(vec2 a, vec2 b, vec2 c, vec2 low) {
    float level = clamp(a.y - low.y, 0.0f, 1.0f);
    return abs(edge_band_integral(a, b, low, level) + edge_band_integral(b, c, low, level) +
               edge_band_integral(c, a, low, level));
}
