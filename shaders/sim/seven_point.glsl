// A SevenPointOperator on the GPU (sim/fluid/StencilOperator.h;
// sim/gpu/GpuStencilOperator.h): one uint of flags per cell, encoded as
// common/stencil_flags.glsl says. Red–black passes run one invocation per
// pair of cells (2i, 2i + 1) of a row, which holds one cell of each colour.
// With REAL defined (float or double: the precision of a pass) and
// STENCIL_INPUT(c) naming the vector the operator reads, it also gives the
// operator itself, from the uniforms size, weight and identity.

#include "common/stencil_flags.glsl"

bool hasFace(uint bits, int axis, int side) { return (bits & (1u << uint(2 * axis + side))) != 0u; }

int cellIndex(ivec3 cell, ivec3 cells) { return cell.x + cells.x * (cell.y + cells.y * cell.z); }

// The cell of `colour` ((i + j + k) % 2) in the pair of invocation `pair`, and the other one.
ivec3 cellOfColour(ivec3 pair, int colour) {
    return ivec3(2 * pair.x + ((pair.y + pair.z + colour) & 1), pair.y, pair.z);
}
ivec3 cellOfOtherColour(ivec3 pair, int colour) { return cellOfColour(pair, 1 - colour); }

#ifdef REAL
uniform ivec3 size;      // cells
uniform dvec3 weight;    // coupling per axis
uniform double identity; // the diagonal's constant term

// identity + Σ w over the class's faces, summed in SevenPointOperator::setWeight's order.
REAL diagonalOf(uint cls) {
    REAL diagonal = REAL(identity);
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side)
            if (hasFace(cls, axis, side)) diagonal += REAL(weight[axis]);
    return diagonal;
}

// Σ_{n coupled to c} w · input_n, in SevenPointOperator::neighbourSum's order.
REAL neighbourSum(int c, uint bits) {
    const int strides[3] = int[3](1, size.x, size.x * size.y);
    REAL sum = REAL(0);
    for (int axis = 0; axis < 3; ++axis) {
        if (hasFace(bits, axis, 0)) sum += REAL(weight[axis]) * STENCIL_INPUT(c - strides[axis]);
        if (hasFace(bits, axis, 1)) sum += REAL(weight[axis]) * STENCIL_INPUT(c + strides[axis]);
    }
    return sum;
}
#endif
