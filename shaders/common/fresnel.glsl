// Unpolarised Fresnel reflectance for light passing from index n_i into n_t
// at incidence cos θi ([Born99] §1.5.2; the reflection term of
// [Ihrke07] eq. 2): the mean of the s and p reflectances, 1 beyond the
// critical angle.
float fresnel_reflectance(float cos_i, float n_i, float n_t) {
    float eta = n_i / n_t;
    float sin_t2 = eta * eta * max(0.0f, 1.0f - cos_i * cos_i);
    if (sin_t2 >= 1.0f) return 1.0f;
    float cos_t = sqrt(1.0f - sin_t2);
    float rs = (n_i * cos_i - n_t * cos_t) / (n_i * cos_i + n_t * cos_t);
    float rp = (n_t * cos_i - n_i * cos_t) / (n_t * cos_i + n_i * cos_t);
    return 0.5f * (rs * rs + rp * rp);
}

// The diffuse (hemispherical) Fresnel reflectance from the side of n_i:
// the share of an isotropic radiance's flux toward the interface that it
// reflects, R_d = 2∫₀¹ R(μ) μ dμ = ∫₀¹ R(√u) du with u = μ². Past the
// critical angle (u < u_c = 1 − (n_t/n_i)², where n_i > n_t) R = 1; on the
// rest u = u_c + (1 − u_c)s² takes out the square-root edge at u_c, and 16
// midpoints in s integrate it (error below 1e-3: tests/unit). For light
// leaving a dense medium R_d is large (n_i/n_t = 1.5: 0.60, 1.33: 0.47);
// from the other side small (1/1.5: 0.09), and the two obey
// 1 − R_d(n_t → n_i) = (n_i/n_t)²·(1 − R_d(n_i → n_t)).
float diffuse_fresnel_reflectance(float n_i, float n_t) {
    float ratio = n_t / n_i;
    float critical = n_i > n_t ? 1.0f - ratio * ratio : 0.0f;
    float sum = 0.0f;
    for (int k = 0; k < 16; ++k) {
        float s = (float(k) + 0.5f) / 16.0f;
        float u = critical + (1.0f - critical) * s * s;
        sum += fresnel_reflectance(sqrt(u), n_i, n_t) * 2.0f * s;
    }
    return critical + (1.0f - critical) * sum / 16.0f;
}
