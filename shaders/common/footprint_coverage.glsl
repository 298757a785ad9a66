// Exact coverage of a texel by a wavefront patch's footprint (the triangle
// its three corner rays span on a receiver), for the intensity-law deposit of
// the wavefront pass ([Ihrke07] §4.2: irradiance is a patch's power over its
// area): the area of triangle ∩ square, by clipping the triangle against the
// square's four edges (Sutherland–Hodgman) and the shoelace formula. Texel
// coordinates: texel (i, j) is the square [i, i+1] × [j, j+1].
// Shared by GLSL and C++ (cpp_shim.h).

// Twice the signed area of the triangle (a, b, c).
float twice_signed_area(vec2 a, vec2 b, vec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
}

// Area of the part of triangle (a, b, c) — either orientation — inside the
// square [low, low + 1]².
float triangle_texel_coverage(vec2 a, vec2 b, vec2 c, vec2 low) {
    vec2 polygon[9];
    vec2 clipped[9];
    polygon[0] = a;
    polygon[1] = b;
    polygon[2] = c;
    int count = 3;
    for (int edge = 0; edge < 4; ++edge) {
        // Edge k keeps the half-plane sign·(p[axis] − bound) ≥ 0.
        int axis = edge / 2;
        float bound = (edge % 2 == 0) ? low[axis] : low[axis] + 1.0f;
        float sign_ = (edge % 2 == 0) ? 1.0f : -1.0f;
        int kept = 0;
        for (int k = 0; k < count; ++k) {
            vec2 p = polygon[k];
            vec2 q = polygon[(k + 1) % count];
            float dp = sign_ * (p[axis] - bound);
            float dq = sign_ * (q[axis] - bound);
            if (dp >= 0.0f) clipped[kept++] = p;
            if ((dp >= 0.0f) != (dq >= 0.0f)) clipped[kept++] = p + (dp / (dp - dq)) * (q - p);
        }
        count = kept;
        for (int k = 0; k < count; ++k) polygon[k] = clipped[k];
        if (count < 3) return 0.0f;
    }
    float twice_area = 0.0f;
    for (int k = 1; k + 1 < count; ++k) twice_area += twice_signed_area(polygon[0], polygon[k], polygon[k + 1]);
    return 0.5f * abs(twice_area);
}
