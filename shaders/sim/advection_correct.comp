// The correction of MacCormack advection ([Selle08] eqs. 4–5) for one field
// on one lattice: the predicted φ̂ⁿ⁺¹ is carried forward again, φ̂ⁿ = φ̂ⁿ⁺¹
// sampled where the characteristic through each sample goes, and half the
// round trip's error is added back, φⁿ⁺¹ = φ̂ⁿ⁺¹ + ½(φⁿ − φ̂ⁿ), clamped to
// the bounds of the predict pass (the limiter of [Selle08] §3.1). In place:
// each sample reads φⁿ where it writes φⁿ⁺¹. Mirrors the second loop of
// advectGroup in sim/fluid/Advection.cpp.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "sim/advection_lattice.glsl"

layout(std430, binding = kSolverField) buffer Field { float values[]; };                 // φⁿ in, φⁿ⁺¹ out
layout(std430, binding = kSolverSource) readonly buffer Source { float predicted[]; };  // φ̂ⁿ⁺¹
layout(std430, binding = kSolverBoundsLow) readonly buffer BoundsLow { float low[]; };
layout(std430, binding = kSolverBoundsHigh) readonly buffer BoundsHigh { float high[]; };
// The displacement records over +Δt (advection_trace.comp); w unused.
layout(std430, binding = kSolverForward) readonly buffer Forward { vec4 ahead[]; };

uniform ivec3 cells;
uniform ivec3 size;  // the field's lattice
uniform int axis;    // −1: cell centres; a: the faces normal to axis a

void main() {
    ivec3 ijk = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(ijk, size))) return;
    uvec2 records = displacementRecords(axis, ijk, cells);
    Stencil s = stencilAt(ijk, 0.5 * (ahead[records.x].xyz + ahead[records.y].xyz), size);
    float corners[8];
    for (int n = 0; n < 8; ++n) corners[n] = predicted[cornerIndex(s, n)];
    float roundTrip = blendCorners(corners, s.t);
    uint here = sampleIndex(ijk, size);
    float corrected = predicted[here] + 0.5 * (values[here] - roundTrip);
    values[here] = clamp(corrected, low[here], high[here]);
}
