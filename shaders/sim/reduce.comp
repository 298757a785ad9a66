// A reduction of one or two solver vectors to a number, in two passes with a
// fixed partition, so the result does not depend on scheduling and a run
// repeats bit for bit (sim/gpu/GpuReduction.h). Accumulates in float64:
// a sum of 2²¹ float32 samples keeps about 1e-15 of its relative error
// instead of 2²¹·6e-8.
//   PASS 0: work group g folds elements g·256 + t, stepping by groups·256,
//           into partials[g];
//   PASS 1: one work group folds the partials into results[slot].
// Variants: OPERATION (REDUCE_SUM, REDUCE_MAX_ABS, REDUCE_DOT) and ELEMENT
// (float or double) of the operands, read at kSolverSource and kSolverTarget.
layout(local_size_x = 256) in;

const int REDUCE_SUM = 0;
const int REDUCE_MAX_ABS = 1;
const int REDUCE_DOT = 2;

layout(std430, binding = kSolverSource) readonly buffer OperandA { ELEMENT a[]; };
layout(std430, binding = kSolverTarget) readonly buffer OperandB { ELEMENT b[]; };
layout(std430, binding = kSolverPartials) buffer Partials { double partials[]; };
layout(std430, binding = kSolverResults) buffer Results { double results[]; };

uniform uint count;   // PASS 0: elements; PASS 1: partials
uniform uint slot;    // PASS 1: where the result goes

shared double folded[256];

double term(uint i) {
    if (OPERATION == REDUCE_MAX_ABS) return abs(double(a[i]));
    if (OPERATION == REDUCE_DOT) return double(a[i]) * double(b[i]);
    return double(a[i]);
}

double combine(double x, double y) { return OPERATION == REDUCE_MAX_ABS ? max(x, y) : x + y; }

void main() {
    uint t = gl_LocalInvocationID.x;
    double value = 0.0lf;
    if (PASS == 0) {
        uint stride = gl_NumWorkGroups.x * 256u;
        for (uint i = gl_WorkGroupID.x * 256u + t; i < count; i += stride) value = combine(value, term(i));
    } else {
        for (uint i = t; i < count; i += 256u) value = combine(value, partials[i]);
    }
    folded[t] = value;
    barrier();
    for (uint span = 128u; span > 0u; span >>= 1) {
        if (t < span) folded[t] = combine(folded[t], folded[t + span]);
        barrier();
    }
    if (t == 0u) {
        if (PASS == 0) partials[gl_WorkGroupID.x] = folded[0];
        else results[slot] = folded[0];
    }
}
