// Boussinesq buoyancy on the faces of one axis (addBuoyancy in
// sim/fluid/Sources.cpp; [Bridson15] §6.2, [Fedkiw01] eq. 8):
// u += Δt·g·(α c − β (T − T_amb)) from the mean of the face's two cells; an
// open face sees its one inside cell; fixed faces are left alone. The
// temperature arrives as T − T_amb (sim/gpu/GpuField.h).
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "sim/fluid_domain.glsl"

layout(std430, binding = kSolverSource) readonly buffer TemperatureExcess { float theta[]; };  // T − T_amb, K
layout(std430, binding = kSolverField) readonly buffer Concentration { float concentration[]; };
layout(std430, binding = kSolverTarget) buffer Velocity { float u[]; };  // faces normal to `axis`, in place

uniform int axis;
uniform float dt_times_g;           // Δt · g_axis, m/s
uniform float thermal_expansion;    // β, 1/K
uniform float concentration_expansion;  // α

float acceleration(ivec3 c) {  // (α c − β ΔT), times g
    int i = c.x + cells.x * (c.y + cells.y * c.z);
    return concentration_expansion * concentration[i] - thermal_expansion * theta[i];
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
    float a = 0.5 * (acceleration(lower) + acceleration(upper));
    u[face.x + size.x * (face.y + size.y * face.z)] += dt_times_g * a;
}
