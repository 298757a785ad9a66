// Sets the samples a scene's sources hold (SceneSources::applyScalars and
// applyVelocity, sim/fluid/Sources.cpp) in one field: held[e] is
// (sample index, float bits of its value), one entry per held sample, each
// sample once (sim/gpu/GpuSources.h), so the entries never race.
layout(local_size_x = 64) in;

#include "sim/entry_index.glsl"

layout(std430, binding = kSolverSourceCells) readonly buffer Held { uvec2 held[]; };
layout(std430, binding = kSolverField) buffer Field { float values[]; };

uniform uint count;

void main() {
    uint e = entryIndex();
    if (e >= count) return;
    values[held[e].x] = uintBitsToFloat(held[e].y);
}
