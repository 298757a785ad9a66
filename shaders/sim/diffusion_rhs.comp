// The right-hand side of backward-Euler diffusion solved for the increment
// ([Stam99] §2.3; sim/fluid/Diffusion.cpp): b_c = −Σ w (φ_c − φ_n) over the
// neighbours n that cell c exchanges with (its diagonal class: free and
// fixed neighbours), i.e. (Δt·D·∇²φ)_c; 0 off the unknowns. In float64 from
// the float32 field, whose reference value cancels in the differences. One
// invocation per cell.
#include "sim/seven_point.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(std430, binding = kSolverField) readonly buffer Field { float phi[]; };
layout(std430, binding = kSolverCells) readonly buffer Cells { uint flags[]; };  // the diffusion operator's
layout(std430, binding = kSolverVectorB) writeonly buffer VectorB { double b[]; };

uniform ivec3 size;    // samples
uniform dvec3 weight;  // Δt·D / h² per axis

void main() {
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(cell, size))) return;
    int c = cellIndex(cell, size);
    uint exchanging = diagonalClass(flags[c]);  // no face bit off the unknowns
    const int strides[3] = int[3](1, size.x, size.x * size.y);
    double centre = double(phi[c]);
    double flux = 0.0lf;
    for (int axis = 0; axis < 3; ++axis) {
        if (hasFace(exchanging, axis, 0)) flux += weight[axis] * (centre - double(phi[c - strides[axis]]));
        if (hasFace(exchanging, axis, 1)) flux += weight[axis] * (centre - double(phi[c + strides[axis]]));
    }
    b[c] = -flux;
}
