// The right-hand side of the pressure projection ([Bridson15] §5.3;
// sim/fluid/PressureSolver.cpp): b = −∇·u on the unknowns of the Poisson
// operator, 0 elsewhere, with (∇·u)_c = Σ_a (u_a(upper face) − u_a(lower face)) / h_a
// (MacGrid::divergence), in float64. One invocation per cell.
#include "sim/seven_point.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(std430, binding = kSolverVelocityX) readonly buffer VelocityX { float u[]; };
layout(std430, binding = kSolverVelocityY) readonly buffer VelocityY { float v[]; };
layout(std430, binding = kSolverVelocityZ) readonly buffer VelocityZ { float w[]; };
layout(std430, binding = kSolverCells) readonly buffer Cells { uint flags[]; };  // the Poisson operator's
layout(std430, binding = kSolverVectorB) writeonly buffer VectorB { double b[]; };

uniform ivec3 size;  // cells
uniform dvec3 h;     // cell edge per axis

void main() {
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(cell, size))) return;
    int c = cellIndex(cell, size);
    if (!isUnknown(flags[c])) {
        b[c] = 0.0lf;
        return;
    }
    int ux = cellIndex(cell, size + ivec3(1, 0, 0));
    int vy = cellIndex(cell, size + ivec3(0, 1, 0));
    int wz = cellIndex(cell, size + ivec3(0, 0, 1));
    double divergence = (double(u[ux + 1]) - double(u[ux])) / h.x +
                        (double(v[vy + size.x]) - double(v[vy])) / h.y +
                        (double(w[wz + size.x * size.y]) - double(w[wz])) / h.z;
    b[c] = -divergence;
}
