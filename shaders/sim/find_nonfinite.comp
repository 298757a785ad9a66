// The first sample of a field that is NaN or ±Inf (FiniteCheck.h on the
// GPU), tested on the bits (exponent all ones), which no compiler setting
// can fold away as it may isnan().
//   FIND:   first[slot] = min(first[slot], index), left at 0xffffffff where
//           every sample is finite;
//   RECORD: one invocation keeps that sample's bits in first[slots + slot],
//           before a later pass can overwrite it.
layout(local_size_x = 256) in;

#include "sim/entry_index.glsl"

layout(std430, binding = kSolverField) readonly buffer Field { float values[]; };
layout(std430, binding = kSolverPartials) buffer FirstBad { uint first[]; };  // uint here, not double

uniform uint count;  // FIND: samples; RECORD: the slots a substep has
uniform uint slot;

void main() {
    uint i = entryIndex();
#ifdef FIND
    if (i >= count) return;
    if ((floatBitsToUint(values[i]) & 0x7f800000u) == 0x7f800000u) atomicMin(first[slot], i);
#else
    if (i > 0u) return;
    uint bad = first[slot];
    if (bad != 0xffffffffu) first[count + slot] = floatBitsToUint(values[bad]);
#endif
}
