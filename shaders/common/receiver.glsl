// Receivers are opaque diffuse squares: a plane through `origin` with unit
// normal, spanned by unit tangents (axis_u, axis_v), of edge `size`, holding a
// map of resolution² irradiance texels.

// Signed distance of x from the receiver plane (positive on the lit side).
float receiver_signed_distance(vec3 x, vec3 origin, vec3 normal) {
    return dot(x - origin, normal);
}

// Map coordinates in [0, 1)² of a point on the plane; outside that range the
// point misses the square.
vec2 receiver_map_coordinates(vec3 hit, vec3 origin, vec3 axis_u, vec3 axis_v, float size) {
    vec3 offset = hit - origin;
    return vec2(dot(offset, axis_u), dot(offset, axis_v)) / size + 0.5f;
}

// Parameter t ≥ 0 where the straight ray x + t·d meets the plane, or -1 when
// it moves away from it or runs parallel.
float receiver_ray_parameter(vec3 x, vec3 d, vec3 origin, vec3 normal) {
    float approach = dot(d, normal);
    if (abs(approach) < 1e-12f) return -1.0f;
    float t = -receiver_signed_distance(x, origin, normal) / approach;
    return t >= 0.0f ? t : -1.0f;
}

// Of a power shared bilinearly between the four texels around map_uv on a
// map of resolution² texels, the part that falls on the map's texels: 1
// inside, less at its edges (the splats of common/caustic_deposits.glsl and
// caustic_splats.vert give those on it the shares of those off it).
float bilinear_share_on_map(vec2 map_uv, int resolution) {
    vec2 texel = map_uv * float(resolution) - 0.5f;
    ivec2 base = ivec2(floor(texel));
    vec2 f = texel - vec2(base);
    float share = 0.0f;
    for (int k = 0; k < 4; ++k) {
        ivec2 offset = ivec2(k & 1, k >> 1);
        vec2 weight = mix(1.0f - f, f, vec2(offset));
        bool inside = all(greaterThanEqual(base + offset, ivec2(0))) && all(lessThan(base + offset, ivec2(resolution)));
        share += inside ? weight.x * weight.y : 0.0f;
    }
    return share;
}
