// Direction and disk sampling for photon emission (pdf-uniform maps from the
// unit square, so stratifying (u1, u2) stratifies the emitted photons).

// A unit vector uniformly distributed over the spherical cap of directions
// within angle acos(cos_max) of `axis`; solid angle 2π(1 − cos_max).
vec3 sample_cone(vec3 axis, vec3 tangent, vec3 bitangent, float cos_max, float u1, float u2) {
    float cos_theta = 1.0f - u1 * (1.0f - cos_max);
    float sin_theta = sqrt(max(0.0f, 1.0f - cos_theta * cos_theta));
    float phi = 2.0f * 3.14159265358979f * u2;
    return cos_theta * axis + sin_theta * (cos(phi) * tangent + sin(phi) * bitangent);
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
