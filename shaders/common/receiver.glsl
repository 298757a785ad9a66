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
