// Beer–Lambert attenuation over a path segment of length ds through a medium
// of extinction κ (1/m per RGB channel): T = exp(−κ·ds) ([Ihrke07] §3, eq. 5).
vec3 beer_lambert_transmittance(vec3 kappa, float ds) {
    return exp(-kappa * ds);
}

// ∫_0^ds exp(−κ·s) ds per channel: the length a unit of power "spends" in a
// segment whose power decays while crossing it. The track-length estimator of
// fluence deposits Φ0 times this (docs/architecture.md, Conventions:
// φ = Σ Φ·ℓ / h³); it tends to ds as κ·ds → 0.
vec3 attenuated_track_length(vec3 kappa, float ds) {
    vec3 optical_depth = kappa * ds;
    vec3 small = ds * (1.0f - 0.5f * optical_depth);
    vec3 large = (1.0f - exp(-optical_depth)) / max(kappa, vec3(1e-30f));
    return mix(large, small, lessThan(optical_depth, vec3(1e-4f)));
}
