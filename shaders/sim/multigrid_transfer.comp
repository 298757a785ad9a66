// The grid transfers of the multigrid V-cycle ([McAdams10] §3;
// sim/fluid/Multigrid.cpp, MultigridPreconditioner::AxisTransfer), separable
// per axis: along a coarsened axis fine cell f interpolates its parent f / 2
// (¾) and the parent's neighbour on f's side (¼, clamped at the ends); along
// an axis that is not coarsened it takes its own cell (½ + ½).
//   TRANSFER_RESTRICT: coarse b = restrictionScale · Pᵀ fine r on the coarse
//                      unknowns, 0 elsewhere; one invocation per coarse cell.
//   TRANSFER_PROLONG:  fine x += P coarse x on the fine unknowns; one
//                      invocation per fine cell.
// The multigrid levels are float32 (sim/gpu/GpuMultigrid.h).
#define TRANSFER_RESTRICT 0
#define TRANSFER_PROLONG 1

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "sim/seven_point.glsl"

// The flags of the level written: the coarse one when restricting, the fine one when prolonging.
layout(std430, binding = kSolverCells) readonly buffer Cells { uint flags[]; };
#if TRANSFER == TRANSFER_RESTRICT
layout(std430, binding = kSolverFine) readonly buffer Fine { float fine[]; };        // the fine residual
layout(std430, binding = kSolverCoarse) writeonly buffer Coarse { float coarse[]; }; // the coarse right-hand side
uniform float restrictionScale;  // 1 / 2^(coarsened axes)
#else
layout(std430, binding = kSolverFine) buffer Fine { float fine[]; };                 // the fine unknowns
layout(std430, binding = kSolverCoarse) readonly buffer Coarse { float coarse[]; };  // the coarse correction
#endif

uniform ivec3 fineSize;
uniform ivec3 coarseSize;
uniform ivec3 coarsened;  // per axis, 1 where the coarse level halves it

int parentOf(int axis, int f) { return coarsened[axis] != 0 ? f / 2 : f; }
int neighbourOf(int axis, int f) {
    if (coarsened[axis] == 0) return f;
    int parent = f / 2;
    return clamp((f & 1) == 0 ? parent - 1 : parent + 1, 0, coarseSize[axis] - 1);
}
float parentWeight(int axis) { return coarsened[axis] != 0 ? 0.75 : 0.5; }
float neighbourWeight(int axis) { return coarsened[axis] != 0 ? 0.25 : 0.5; }

#if TRANSFER == TRANSFER_RESTRICT
// Pᵀ's weight of fine cell f (along `axis`) in coarse cell parent.
float restrictionWeight(int axis, int parent, int f) {
    if (f < 0 || f >= fineSize[axis]) return 0.0;
    float w = 0.0;
    if (parentOf(axis, f) == parent) w += parentWeight(axis);
    if (neighbourOf(axis, f) == parent) w += neighbourWeight(axis);
    return w;
}

void main() {
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(cell, coarseSize))) return;
    int c = cellIndex(cell, coarseSize);
    if (!isUnknown(flags[c])) {
        coarse[c] = 0.0;
        return;
    }
    // The fine cells of coarse cell C lie in [2C − 1, 2C + 2] along a coarsened axis, at C otherwise.
    ivec3 first = ivec3(coarsened.x != 0 ? 2 * cell.x - 1 : cell.x, coarsened.y != 0 ? 2 * cell.y - 1 : cell.y,
                        coarsened.z != 0 ? 2 * cell.z - 1 : cell.z);
    float sum = 0.0;
    for (int a = 0; a < 4; ++a) {
        int fk = first.z + a;
        float wz = restrictionWeight(2, cell.z, fk);
        if (wz == 0.0) continue;
        for (int b = 0; b < 4; ++b) {
            int fj = first.y + b;
            float wyz = wz * restrictionWeight(1, cell.y, fj);
            if (wyz == 0.0) continue;
            for (int d = 0; d < 4; ++d) {
                int fi = first.x + d;
                float w = wyz * restrictionWeight(0, cell.x, fi);
                if (w != 0.0) sum += w * fine[cellIndex(ivec3(fi, fj, fk), fineSize)];
            }
        }
    }
    coarse[c] = restrictionScale * sum;
}
#else
void main() {
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(cell, fineSize))) return;
    int f = cellIndex(cell, fineSize);
    if (!isUnknown(flags[f])) return;
    ivec3 parents = ivec3(parentOf(0, cell.x), parentOf(1, cell.y), parentOf(2, cell.z));
    ivec3 neighbours = ivec3(neighbourOf(0, cell.x), neighbourOf(1, cell.y), neighbourOf(2, cell.z));
    float correction = 0.0;
    for (int a = 0; a < 2; ++a) {
        int ck = a == 0 ? parents.z : neighbours.z;
        float wz = a == 0 ? parentWeight(2) : neighbourWeight(2);
        for (int b = 0; b < 2; ++b) {
            int cj = b == 0 ? parents.y : neighbours.y;
            float wyz = wz * (b == 0 ? parentWeight(1) : neighbourWeight(1));
            correction += wyz * (parentWeight(0) * coarse[cellIndex(ivec3(parents.x, cj, ck), coarseSize)] +
                                 neighbourWeight(0) * coarse[cellIndex(ivec3(neighbours.x, cj, ck), coarseSize)]);
        }
    }
    fine[f] += correction;
}
#endif
