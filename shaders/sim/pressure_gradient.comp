// The velocity update of the pressure projection ([Bridson15] §5.1–5.3;
// sim/fluid/PressureSolver.cpp): u_a −= (p_upper − p_lower) / h_a on every
// free face, p = 0 beyond an open face; faces on a closed wall or touching a
// solid are fixed at 0 (FluidDomain::faceIsFixed). Also writes the float32
// pressure. One invocation per point of the (n + 1)³ lattice: the x, y and z
// faces with that index and, inside the grid, the cell.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(std430, binding = kSolverVelocityX) buffer VelocityX { float u[]; };
layout(std430, binding = kSolverVelocityY) buffer VelocityY { float v[]; };
layout(std430, binding = kSolverVelocityZ) buffer VelocityZ { float w[]; };
layout(std430, binding = kSolverCells) readonly buffer Cells { uint solid[]; };  // per cell, 1 = solid
layout(std430, binding = kSolverVectorX) readonly buffer VectorX { double p[]; };   // the solution
layout(std430, binding = kSolverTarget) writeonly buffer Target { float pressure[]; };

uniform ivec3 size;         // cells
uniform dvec3 inverseH;     // 1 / cell edge per axis
uniform uint openFaces;     // bit 2·axis + side: that face of the box is open

int cellIndex(ivec3 cell) { return cell.x + size.x * (cell.y + size.y * cell.z); }
bool isSolid(ivec3 cell) { return solid[cellIndex(cell)] != 0u; }
bool isOpen(int axis, int side) { return (openFaces & (1u << uint(2 * axis + side))) != 0u; }

// FluidDomain::faceIsFixed for the face of `axis` between cells index − e_axis and index.
bool faceIsFixed(int axis, ivec3 upper) {
    ivec3 lower = upper;
    lower[axis] -= 1;
    if (lower[axis] < 0) return !isOpen(axis, 0) || isSolid(upper);
    if (upper[axis] >= size[axis]) return !isOpen(axis, 1) || isSolid(lower);
    return isSolid(lower) || isSolid(upper);
}

// The velocity on that face after the projection, from its value before.
float projected(int axis, ivec3 upper, float velocity) {
    if (faceIsFixed(axis, upper)) return 0.0;
    ivec3 lower = upper;
    lower[axis] -= 1;
    double pLower = lower[axis] >= 0 ? p[cellIndex(lower)] : 0.0lf;
    double pUpper = upper[axis] < size[axis] ? p[cellIndex(upper)] : 0.0lf;
    return float(double(velocity) - (pUpper - pLower) * inverseH[axis]);
}

void main() {
    ivec3 index = ivec3(gl_GlobalInvocationID);
    if (any(greaterThan(index, size))) return;
    ivec3 faces[3] = ivec3[3](size + ivec3(1, 0, 0), size + ivec3(0, 1, 0), size + ivec3(0, 0, 1));
    if (all(lessThan(index, faces[0]))) {
        int f = index.x + faces[0].x * (index.y + faces[0].y * index.z);
        u[f] = projected(0, index, u[f]);
    }
    if (all(lessThan(index, faces[1]))) {
        int f = index.x + faces[1].x * (index.y + faces[1].y * index.z);
        v[f] = projected(1, index, v[f]);
    }
    if (all(lessThan(index, faces[2]))) {
        int f = index.x + faces[2].x * (index.y + faces[2].y * index.z);
        w[f] = projected(2, index, w[f]);
    }
    if (all(lessThan(index, size))) pressure[cellIndex(index)] = float(p[cellIndex(index)]);
}
