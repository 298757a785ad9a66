// Vorticity confinement's force on the faces of one axis ([Fedkiw01]
// eqs. 10–11; sim/fluid/VorticityConfinement.cpp): at each of the face's
// two cells f = ε h (N × ω), N = ∇|ω| / |∇|ω|| by central differences of
// vorticity.comp's |ω| (zero where |∇|ω|| < min_gradient, and in solid
// cells); u += Δt times the mean over the two cells (an open face sees its
// one inside cell); fixed faces are left alone.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "sim/fluid_domain.glsl"

layout(std430, binding = kSolverVorticity) readonly buffer Vorticity { vec4 omega[]; };  // (ω, |ω|)
layout(std430, binding = kSolverTarget) buffer Velocity { float velocity[]; };  // faces normal to `axis`, in place

uniform int axis;
uniform vec3 h;              // cell edges, m
uniform float scale;         // ε h, m
uniform float dt;            // s
uniform float min_gradient;  // kMinVorticityGradient, 1/(m·s)

vec4 omegaAt(ivec3 c) { return omega[c.x + cells.x * (c.y + cells.y * c.z)]; }

// ∂|ω|/∂x_a at cell c.
float magnitudeDerivative(ivec3 c, int a) {
    ivec3 low = c;
    ivec3 high = c;
    low[a] = max(c[a] - 1, 0);
    high[a] = min(c[a] + 1, cells[a] - 1);
    if (high[a] == low[a]) return 0.0;
    return (omegaAt(high).w - omegaAt(low).w) / (float(high[a] - low[a]) * h[a]);
}

// Component `axis` of the force at cell c, m/s².
float force(ivec3 c) {
    if (isSolidCell(c)) return 0.0;
    vec3 eta = vec3(magnitudeDerivative(c, 0), magnitudeDerivative(c, 1), magnitudeDerivative(c, 2));
    float length_eta = length(eta);
    if (length_eta < min_gradient) return 0.0;
    return scale * cross(eta / length_eta, omegaAt(c).xyz)[axis];
}

void main() {
    ivec3 face = ivec3(gl_GlobalInvocationID);
    ivec3 size = cells;
    size[axis] += 1;
    if (any(greaterThanEqual(face, size))) return;
    if (faceIsFixed(axis, face)) return;
    ivec3 upper = face;
    ivec3 lower = face;
    lower[axis] -= 1;
    if (lower[axis] < 0) lower = upper;
    if (upper[axis] >= cells[axis]) upper = lower;
    velocity[face.x + size.x * (face.y + size.y * face.z)] += dt * 0.5 * (force(lower) + force(upper));
}
