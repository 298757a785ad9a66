// The water surface's wave equation on the GPU (sim/gpu/GpuWaterBody.h),
// the arithmetic of sim/deform/WaterSurface.cpp in the same order and in
// float64, so that both give the same heights:
//   EIKON_PASS 0, a step: with the five-point Laplacian L, mirrored at the
//     walls (∂h/∂n = 0), and the moving disturbances' force f,
//       v^{n+½} = ((1 − γΔt/2)·v^{n−½} + Δt·(c²·L h^n + f^n)) / (1 + γΔt/2),
//       h^{n+1} = h^n + Δt·v^{n+½},
//     reading h^n and writing h^{n+1} into the other height buffer;
//   EIKON_PASS 1, a drop: h −= its Gaussian dip, which the host computed
//     once per drop.
// GLSL has no float64 exp: a disturbance's Gaussian takes precise_exp
// below, within an ulp or two of the host's, so its heights agree to
// float64 rounding of the force. One invocation per node, x fastest.
layout(local_size_x = 256) in;

#include "sim/entry_index.glsl"

#if EIKON_PASS == 0
layout(std430, binding = kWaterHeight) readonly buffer WaterHeight { double height[]; };
layout(std430, binding = kWaterNextHeight) writeonly buffer WaterNextHeight { double next_height[]; };
layout(std430, binding = kWaterVelocity) buffer WaterVelocity { double velocity[]; };

const int kMaxMovers = EIKON_MAX_WATER_MOVERS;

uniform ivec2 nodes;
uniform double weight_x, weight_z;  // 1/Δx², 1/Δz²
uniform double wave_speed_squared;  // c²
uniform double step_seconds;        // Δt
uniform double half_damping;        // γΔt/2
uniform dvec2 basin_min, spacing;   // node (i, k) lies at basin_min + (i, k)·spacing (x, z)
uniform int movers;                 // disturbances pushing now
uniform dvec4 mover[kMaxMovers];    // (centre x, centre z, strength, radius)

// exp in float64: e^x = 2^k · e^r with r = x − k·ln 2 in [−ln2/2, ln2/2],
// e^r by its Taylor series (18 terms: the 19th is below 1e-19).
double precise_exp(double x) {
    const double kLn2 = 0.6931471805599453lf;
    if (x < -745.0lf) return 0.0lf;
    double k = floor(x / kLn2 + 0.5lf);
    precise double r = x - k * kLn2;
    precise double term = 1.0lf, sum = 1.0lf;
    for (int n = 1; n <= 18; ++n) {
        term *= r / double(n);
        sum += term;
    }
    return ldexp(sum, int(k));
}

void main() {
    uint n = entryIndex();
    if (n >= uint(nodes.x * nodes.y)) return;
    int i = int(n) % nodes.x, k = int(n) / nodes.x;
    precise double centre = height[n];
    precise double sum = 0.0lf;
    if (i > 0) sum += weight_x * (height[n - 1u] - centre);
    if (i + 1 < nodes.x) sum += weight_x * (height[n + 1u] - centre);
    if (k > 0) sum += weight_z * (height[n - uint(nodes.x)] - centre);
    if (k + 1 < nodes.y) sum += weight_z * (height[n + uint(nodes.x)] - centre);
    precise double acceleration = sum * wave_speed_squared;
    for (int m = 0; m < movers; ++m) {
        precise dvec2 d = (basin_min + dvec2(double(i) * spacing.x, double(k) * spacing.y)) - mover[m].xy;
        acceleration -= mover[m].z * precise_exp(-dot(d, d) / (2.0lf * mover[m].w * mover[m].w));
    }
    precise double v = ((1.0lf - half_damping) * velocity[n] + step_seconds * acceleration) / (1.0lf + half_damping);
    velocity[n] = v;
    next_height[n] = centre + step_seconds * v;
}
#else
layout(std430, binding = kWaterHeight) buffer WaterHeight { double height[]; };
layout(std430, binding = kWaterDrop) readonly buffer WaterDrop { double dip[]; };

uniform int node_count;

void main() {
    uint n = entryIndex();
    if (n >= uint(node_count)) return;
    height[n] -= dip[n];
}
#endif
