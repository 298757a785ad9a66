// Traces the characteristics of MacCormack advection ([Selle08] eqs. 3–5)
// through the velocity at the start of the step, by the midpoint rule
// ([Stam99] §2.2), in cell coordinates g (cell (i, j, k) centred at
// (i, j, k) + ½): d(±Δt) = ±Δt · u(g ± ½Δt · u(g)), u in cells per second.
// One invocation per displacement record (sim/advection_lattice.glsl): every
// cell centre, whose velocity is the mean of its two faces per axis, and every
// face on a wall of the grid, whose velocity is sampled there. Mirrors
// traceCellCentres and LatticeEnds::traced of sim/fluid/Advection.cpp; the
// backward and forward steps start from the same velocity.
layout(local_size_x = 64) in;

#include "sim/entry_index.glsl"

#include "sim/advection_lattice.glsl"

layout(std430, binding = kSolverVelocityX) readonly buffer VelocityX { float u[]; };
layout(std430, binding = kSolverVelocityY) readonly buffer VelocityY { float v[]; };
layout(std430, binding = kSolverVelocityZ) readonly buffer VelocityZ { float w[]; };
// The records' displacements over −Δt and +Δt in cells; w unused.
layout(std430, binding = kSolverBackward) writeonly buffer Backward { vec4 back[]; };
layout(std430, binding = kSolverForward) writeonly buffer Forward { vec4 ahead[]; };

uniform ivec3 cells;
uniform vec3 cellsPerMetre;  // 1 / h per axis: face velocities in m/s to cells per second
uniform float dt;

float faceVelocity(int axis, uint index) { return axis == 0 ? u[index] : (axis == 1 ? v[index] : w[index]); }

// The velocity in cells per second at cell coordinate g, each component
// trilinear on its own face lattice (MacGrid::velocityAt).
vec3 velocityAt(vec3 g) {
    vec3 velocity;
    for (int axis = 0; axis < 3; ++axis) {
        ivec3 size = cells;
        size[axis] += 1;
        vec3 offset = vec3(0.5);
        offset[axis] = 0.0;
        Stencil s = stencilAt(ivec3(0), g - offset, size);
        float corners[8];
        for (int n = 0; n < 8; ++n) corners[n] = faceVelocity(axis, cornerIndex(s, n));
        velocity[axis] = blendCorners(corners, s.t);
    }
    return velocity * cellsPerMetre;
}

// The velocity at the centre of `cell`: the mean of its two faces per axis.
vec3 cellCentreVelocity(ivec3 cell) {
    vec3 velocity;
    for (int axis = 0; axis < 3; ++axis) {
        ivec3 size = cells;
        size[axis] += 1;
        ivec3 above = cell;
        above[axis] += 1;
        velocity[axis] =
            0.5 * (faceVelocity(axis, sampleIndex(cell, size)) + faceVelocity(axis, sampleIndex(above, size)));
    }
    return velocity * cellsPerMetre;
}

void main() {
    uint record = entryIndex();
    if (record >= recordCount(cells)) return;
    uint cellCount = uint(cells.x * cells.y * cells.z);
    vec3 start;
    vec3 velocity;
    if (record < cellCount) {
        ivec3 cell = ivec3(record % uint(cells.x), (record / uint(cells.x)) % uint(cells.y),
                           record / uint(cells.x * cells.y));
        start = vec3(cell) + 0.5;
        velocity = cellCentreVelocity(cell);
    } else {
        int axis = 0;
        uint wall = record - cellCount;
        while (wall >= 2u * wallFaceCount(axis, cells)) {
            wall -= 2u * wallFaceCount(axis, cells);
            ++axis;
        }
        ivec2 across = axesAcross(axis);
        uint perWall = wallFaceCount(axis, cells);
        uint onWall = wall % perWall;
        ivec3 face;
        face[axis] = wall < perWall ? 0 : cells[axis];
        face[across.x] = int(onWall % uint(cells[across.x]));
        face[across.y] = int(onWall / uint(cells[across.x]));
        start = vec3(face) + 0.5;
        start[axis] = float(face[axis]);
        velocity = velocityAt(start);
    }
    back[record] = vec4(-dt * velocityAt(start - 0.5 * dt * velocity), 0.0);
    ahead[record] = vec4(dt * velocityAt(start + 0.5 * dt * velocity), 0.0);
}
