// The semi-Lagrangian step of MacCormack advection ([Selle08] eq. 3,
// [Stam99] §2.2) for one field on one lattice: φ̂ⁿ⁺¹ = φⁿ sampled where the
// characteristic through each sample came from, and the smallest and largest
// of the eight values that sample blends — the limiter's bounds ([Selle08]
// §3.1). Mirrors the first loop of advectGroup in sim/fluid/Advection.cpp.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "sim/advection_lattice.glsl"

layout(std430, binding = kSolverSource) readonly buffer Source { float start[]; };        // φⁿ
layout(std430, binding = kSolverTarget) writeonly buffer Target { float predicted[]; };  // φ̂ⁿ⁺¹
layout(std430, binding = kSolverBoundsLow) writeonly buffer BoundsLow { float low[]; };
layout(std430, binding = kSolverBoundsHigh) writeonly buffer BoundsHigh { float high[]; };
// The displacement records over −Δt (advection_trace.comp); w unused.
layout(std430, binding = kSolverBackward) readonly buffer Backward { vec4 back[]; };

uniform ivec3 cells;
uniform ivec3 size;  // the field's lattice
uniform int axis;    // −1: cell centres; a: the faces normal to axis a

void main() {
    ivec3 ijk = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(ijk, size))) return;
    uvec2 records = displacementRecords(axis, ijk, cells);
    Stencil s = stencilAt(ijk, 0.5 * (back[records.x].xyz + back[records.y].xyz), size);
    float corners[8];
    for (int n = 0; n < 8; ++n) corners[n] = start[cornerIndex(s, n)];
    float smallest = corners[0], largest = corners[0];
    for (int n = 1; n < 8; ++n) {
        smallest = min(smallest, corners[n]);
        largest = max(largest, corners[n]);
    }
    uint here = sampleIndex(ijk, size);
    predicted[here] = blendCorners(corners, s.t);
    low[here] = smallest;
    high[here] = largest;
}
