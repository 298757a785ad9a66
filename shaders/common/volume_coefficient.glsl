// An imported volume's (or a library caller's) extinction κ or scattering
// σs in one channel of a cell (sim/optics/VolumeOptics.h): the medium's,
// plus the per-density coefficient times the density clamped at 0, plus a
// grid's own, plus the flame's soot term, summed in this order in float64.
// Shared by GLSL and C++: VolumeOptics.cpp maps host arrays through it, and
// shaders/caller_fields.comp a caller's GL buffers, so that both paths form
// the same float64 and round the same κ and σs to float32.
double volume_coefficient(double medium, double per_density, double density, double grid, double flame) {
    double rho = max(0.0, density);  // ρ finite (refused otherwise)
    precise double sum = medium + per_density * rho + grid + flame;
    return sum;
}
