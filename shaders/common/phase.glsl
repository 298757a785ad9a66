// Henyey–Greenstein phase function ([Ihrke07] §3, eqs. 3, 6; Henyey–Greenstein named in §5.1), normalised so
// that its integral over the sphere is 1 (units 1/sr):
//   p(θ) = (1 − g²) / (4π · (1 + g² − 2g·cosθ)^{3/2}),   −1 < g < 1.
float henyey_greenstein(float cos_theta, float g) {
    float g2 = g * g;
    float denominator = 1.0f + g2 - 2.0f * g * cos_theta;
    return (1.0f - g2) / (4.0f * 3.14159265358979f * denominator * sqrt(denominator));
}
