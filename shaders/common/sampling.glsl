// Direction and disk sampling for photon emission (pdf-uniform maps from the
// unit square, so stratifying (u1, u2) stratifies the emitted photons).

// The direction at angle θ from `axis`, versine 1 − cos θ = h, and azimuth
// 2π·u2: built in the cone's own frame from h itself, so that a cone a
// hundredth of a degree wide (h ≈ 1.5e-8, below float's step at 1) keeps its
// width: sin θ = √(h(2 − h)).
vec3 cone_direction(vec3 axis, vec3 tangent, vec3 bitangent, float h, float u2) {
    float sin_theta = sqrt(max(0.0f, h * (2.0f - h)));
    float phi = 2.0f * 3.14159265358979f * u2;
    return (1.0f - h) * axis + sin_theta * (cos(phi) * tangent + sin(phi) * bitangent);
}

// A unit vector uniformly distributed over the spherical cap of directions
// within the half-angle α of `axis` whose versine 1 − cos α is versine_max
// (2: the whole sphere); solid angle 2π·versine_max. Uniform in h = 1 − cos θ.
vec3 sample_cone(vec3 axis, vec3 tangent, vec3 bitangent, float versine_max, float u1, float u2) {
    return cone_direction(axis, tangent, bitangent, u1 * versine_max, u2);
}

// A point uniformly distributed over the unit disk ([Shirley97] concentric
// map, which keeps strata compact).
vec2 sample_disk_concentric(float u1, float u2) {
    float a = 2.0f * u1 - 1.0f;
    float b = 2.0f * u2 - 1.0f;
    if (a == 0.0f && b == 0.0f) return vec2(0.0f);
    float quarter_pi = 0.785398163397448f;
    if (abs(a) > abs(b)) return a * vec2(cos(quarter_pi * b / a), sin(quarter_pi * b / a));
    return b * vec2(cos(2.0f * quarter_pi - quarter_pi * a / b), sin(2.0f * quarter_pi - quarter_pi * a / b));
}

// A direction about the unit normal with pdf cos θ / π (Lambertian
// reflection), by projecting a uniform disk sample up onto the hemisphere.
vec3 sample_cosine_hemisphere(vec3 normal, vec3 tangent, vec3 bitangent, float u1, float u2) {
    vec2 disk = sample_disk_concentric(u1, u2);
    float up = sqrt(max(0.0f, 1.0f - dot(disk, disk)));
    return disk.x * tangent + disk.y * bitangent + up * normal;
}
