// Red–black Gauss–Seidel on the seven-point operator ([Saad03] §4.1 with the
// red–black ordering of §12.4.1; sim/fluid/StencilOperator.h, Multigrid.cpp,
// GaussSeidelIteration.h). A half-sweep updates the cells of `colour`
// ((i + j + k) % 2) from the other colour only, so its invocations, one per
// pair of cells along x, never race.
//   RELAX_SMOOTH:       x_c = (b_c + Σ w x_n) / diag_c   (the multigrid smoother,
//                       SevenPointOperator::relaxSlice)
//   RELAX_GAUSS_SEIDEL: x_c += r_c / diag_c with r_c = b_c − (A x)_c, and r_c
//                       kept at VectorR (0 off the unknowns) for the stopping
//                       test (GaussSeidelIteration.h)
//   With fromZero (the first half-sweep from x = 0): colour's cells take
//   b / diag, the other colour is cleared (relaxSliceFromZero).
//   RELAX_COARSEST:     one work group solves the coarsest multigrid level
//                       (every axis under 4 cells: at most 27): from x = 0,
//                       `sweeps` symmetric sweeps, colours (0, 1, 1, 0).
// REAL: float on the multigrid levels (bound at VectorX/B), double for
// diffusion.
#define RELAX_SMOOTH 0
#define RELAX_GAUSS_SEIDEL 1
#define RELAX_COARSEST 2

#if RELAX == RELAX_COARSEST
layout(local_size_x = 64) in;
#else
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
#endif

layout(std430, binding = kSolverCells) readonly buffer Cells { uint flags[]; };
layout(std430, binding = kSolverVectorB) readonly buffer VectorB { REAL b[]; };
#if RELAX == RELAX_COARSEST
layout(std430, binding = kSolverVectorX) coherent buffer VectorX { REAL x[]; };  // shared by the work group
uniform int sweeps;
#else
layout(std430, binding = kSolverVectorX) buffer VectorX { REAL x[]; };
uniform int colour;
uniform bool fromZero;
#endif
#if RELAX == RELAX_GAUSS_SEIDEL
layout(std430, binding = kSolverVectorR) writeonly buffer VectorR { REAL r[]; };
#endif

#define STENCIL_INPUT(c) x[c]
#include "sim/seven_point.glsl"

// The update of cell c from the other colour's values.
void relax(int c) {
    uint cellFlags = flags[c];
    if (!isUnknown(cellFlags)) {  // x stays 0
#if RELAX == RELAX_GAUSS_SEIDEL
        r[c] = REAL(0);
#endif
        return;
    }
    REAL inverseDiagonal = REAL(1) / diagonalOf(diagonalClass(cellFlags));
#if RELAX == RELAX_GAUSS_SEIDEL
    REAL residual = b[c] + neighbourSum(c, coupledBits(cellFlags)) - diagonalOf(diagonalClass(cellFlags)) * x[c];
    x[c] += residual * inverseDiagonal;
    r[c] = residual;
#else
    x[c] = (b[c] + neighbourSum(c, coupledBits(cellFlags))) * inverseDiagonal;
#endif
}

#if RELAX == RELAX_COARSEST
void halfSweep(int sweepColour, int count) {
    for (int c = int(gl_LocalInvocationID.x); c < count; c += 64) {
        ivec3 cell = ivec3(c % size.x, (c / size.x) % size.y, c / (size.x * size.y));
        if (((cell.x + cell.y + cell.z) & 1) == sweepColour) relax(c);
    }
    memoryBarrierBuffer();
    barrier();
}

void main() {
    int count = size.x * size.y * size.z;
    for (int c = int(gl_LocalInvocationID.x); c < count; c += 64) x[c] = REAL(0);
    memoryBarrierBuffer();
    barrier();
    for (int s = 0; s < sweeps; ++s) {
        halfSweep(0, count);
        halfSweep(1, count);
        halfSweep(1, count);
        halfSweep(0, count);
    }
}
#else
void main() {
    ivec3 pair = ivec3(gl_GlobalInvocationID);
    ivec3 cell = cellOfColour(pair, colour);
    if (pair.y >= size.y || pair.z >= size.z) return;
    if (fromZero) {
        ivec3 other = cellOfOtherColour(pair, colour);
        if (other.x < size.x) {
            int o = cellIndex(other, size);
            x[o] = REAL(0);
        }
        if (cell.x >= size.x) return;
        int c = cellIndex(cell, size);
        uint cellFlags = flags[c];
        bool unknown = isUnknown(cellFlags);
        x[c] = unknown ? b[c] * (REAL(1) / diagonalOf(diagonalClass(cellFlags))) : REAL(0);
#if RELAX == RELAX_GAUSS_SEIDEL
        r[c] = unknown ? b[c] : REAL(0);  // the residual met, from x = 0
#endif
        return;
    }
    if (cell.x >= size.x) return;
    relax(cellIndex(cell, size));
}
#endif
