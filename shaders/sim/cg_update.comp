// The vector updates of preconditioned conjugate gradients ([Saad03]
// Alg. 9.1; sim/fluid/ConjugateGradient.cpp), their scalars read where the
// reductions left them (results[slot], sim/gpu/GpuReduction.h), so a step
// needs nothing from the host:
//   UPDATE_STEP:        α = ρ / (p · q); x += α p, r −= α q
//   UPDATE_DIRECTION:   β = ρ_next / ρ; p = z + β p   (z at VectorQ)
//   UPDATE_REMOVE_MEAN: v −= Σv / (unknowns) on the unknowns, 0 elsewhere,
//                       with Σv over all cells (zero off the unknowns); v
//                       is the vector at VectorR (SevenPointOperator::removeMeanOverUnknowns)
// One invocation per entry.
#define UPDATE_STEP 0
#define UPDATE_DIRECTION 1
#define UPDATE_REMOVE_MEAN 2

layout(local_size_x = 256) in;

#include "sim/entry_index.glsl"

layout(std430, binding = kSolverResults) readonly buffer Results { double results[]; };
#if UPDATE == UPDATE_STEP
layout(std430, binding = kSolverVectorX) buffer VectorX { double x[]; };
layout(std430, binding = kSolverVectorR) buffer VectorR { double r[]; };
layout(std430, binding = kSolverVectorP) readonly buffer VectorP { double p[]; };
layout(std430, binding = kSolverVectorQ) readonly buffer VectorQ { double q[]; };
uniform uint rhoSlot;        // r · z
uniform uint curvatureSlot;  // p · A p
#elif UPDATE == UPDATE_DIRECTION
layout(std430, binding = kSolverVectorP) buffer VectorP { double p[]; };
layout(std430, binding = kSolverVectorQ) readonly buffer VectorQ { double z[]; };
uniform uint rhoSlot;      // r · z of the last step
uniform uint nextRhoSlot;  // r · z of this one
#else
#include "sim/seven_point.glsl"
layout(std430, binding = kSolverCells) readonly buffer Cells { uint flags[]; };
layout(std430, binding = kSolverVectorR) buffer VectorR { double v[]; };
uniform uint sumSlot;
uniform uint unknowns;
#endif

uniform uint count;

void main() {
    uint i = entryIndex();
    if (i >= count) return;
#if UPDATE == UPDATE_STEP
    double alpha = results[rhoSlot] / results[curvatureSlot];
    x[i] += alpha * p[i];
    r[i] -= alpha * q[i];
#elif UPDATE == UPDATE_DIRECTION
    double beta = results[nextRhoSlot] / results[rhoSlot];
    p[i] = z[i] + beta * p[i];
#else
    double mean = results[sumSlot] / double(unknowns);
    v[i] = isUnknown(flags[i]) ? v[i] - mean : 0.0lf;
#endif
}
