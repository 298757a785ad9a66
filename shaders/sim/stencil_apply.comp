// The seven-point operator applied to a vector, one invocation per cell
// (sim/fluid/StencilOperator.h, sim/gpu/GpuStencilOperator.h):
//   OPERATION_APPLY:            q = A p                       (CG's A·p)
//   OPERATION_RESIDUAL:         r = b − A x on the cells of `colour` (all for
//                               −1), 0 on the others: after a half-sweep over
//                               the other colour, the whole residual
//                               (SevenPointOperator::residualSliceAfterSweep)
//   OPERATION_INVERSE_DIAGONAL: z = r / diag                  (the Jacobi preconditioner)
// Cells that are no unknown get 0. REAL is the vectors' element type: double
// for CG, float for the multigrid levels, which bind their float vectors at
// the VectorX/B/R points.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#define OPERATION_APPLY 0
#define OPERATION_RESIDUAL 1
#define OPERATION_INVERSE_DIAGONAL 2

layout(std430, binding = kSolverCells) readonly buffer Cells { uint flags[]; };

#if OPERATION == OPERATION_APPLY
layout(std430, binding = kSolverVectorP) readonly buffer VectorP { REAL p[]; };
layout(std430, binding = kSolverVectorQ) writeonly buffer VectorQ { REAL q[]; };
#elif OPERATION == OPERATION_RESIDUAL
layout(std430, binding = kSolverVectorX) readonly buffer VectorX { REAL x[]; };
layout(std430, binding = kSolverVectorB) readonly buffer VectorB { REAL b[]; };
layout(std430, binding = kSolverVectorR) writeonly buffer VectorR { REAL r[]; };
uniform int colour;  // the cells whose residual is computed; −1: all
#else
layout(std430, binding = kSolverVectorR) readonly buffer VectorR { REAL r[]; };
layout(std430, binding = kSolverVectorQ) writeonly buffer VectorQ { REAL z[]; };
#endif

#if OPERATION == OPERATION_APPLY
#define STENCIL_INPUT(c) p[c]
#elif OPERATION == OPERATION_RESIDUAL
#define STENCIL_INPUT(c) x[c]
#else
#define STENCIL_INPUT(c) r[c]  // (no neighbour is read)
#endif
#include "sim/seven_point.glsl"

void main() {
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(cell, size))) return;
    int c = cellIndex(cell, size);
    uint cellFlags = flags[c];
    bool unknown = isUnknown(cellFlags);
#if OPERATION == OPERATION_APPLY
    q[c] = unknown ? diagonalOf(diagonalClass(cellFlags)) * p[c] - neighbourSum(c, coupledBits(cellFlags)) : REAL(0);
#elif OPERATION == OPERATION_RESIDUAL
    bool wanted = colour < 0 || ((cell.x + cell.y + cell.z) & 1) == colour;
    r[c] = unknown && wanted
               ? b[c] - (diagonalOf(diagonalClass(cellFlags)) * x[c] - neighbourSum(c, coupledBits(cellFlags)))
               : REAL(0);
#else
    z[c] = unknown ? r[c] * (REAL(1) / diagonalOf(diagonalClass(cellFlags))) : REAL(0);  // r · inverseDiagonal, as the CPU
#endif
}
