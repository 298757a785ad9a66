// Between the linear solvers' float64 vectors and float32 samples
// (sim/gpu/GpuMultigrid.h, GpuDiffusion.h), one invocation per entry:
//   CONVERT_NARROW: field = float(vector)   (CG's residual into the multigrid's finest level)
//   CONVERT_WIDEN:  vector = double(field)  (the V-cycle's result back to CG)
//   CONVERT_ADD:    field = float(field + vector)  (a diffusion increment onto its field)
// `vector` is the float64 vector at VectorX, `field` the float32 one at Field.
#define CONVERT_NARROW 0
#define CONVERT_WIDEN 1
#define CONVERT_ADD 2

layout(local_size_x = 256) in;

#include "sim/entry_index.glsl"

layout(std430, binding = kSolverVectorX) buffer VectorX { double vector[]; };
layout(std430, binding = kSolverField) buffer Field { float field[]; };

uniform uint count;

void main() {
    uint i = entryIndex();
    if (i >= count) return;
#if CONVERT == CONVERT_NARROW
    field[i] = float(vector[i]);
#elif CONVERT == CONVERT_WIDEN
    vector[i] = double(field[i]);
#else
    field[i] = float(double(field[i]) + vector[i]);
#endif
}
