// enforceVelocityBoundaries (sim/fluid/Boundaries.cpp) for one velocity
// component: every fixed face (closed wall, next to a solid) is set to zero.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "sim/fluid_domain.glsl"

layout(std430, binding = kSolverTarget) buffer Velocity { float u[]; };  // faces normal to `axis`, in place

uniform int axis;

void main() {
    ivec3 face = ivec3(gl_GlobalInvocationID);
    ivec3 size = cells;
    size[axis] += 1;
    if (any(greaterThanEqual(face, size))) return;
    if (faceIsFixed(axis, face)) u[face.x + size.x * (face.y + size.y * face.z)] = 0.0;
}
