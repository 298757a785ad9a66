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
