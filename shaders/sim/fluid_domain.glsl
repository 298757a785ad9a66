// Where the fluid may go, on the GPU: FluidDomain::faceIsFixed of
// sim/fluid/Boundaries.h ([Bridson15] §5.1). Binds the solid flags (one uint
// per cell, non-zero = solid) at kSolverCells; the including pass sets
// `cells` and `open_faces` (bit 2·axis + side: that face of the box is open).
layout(std430, binding = kSolverCells) readonly buffer Cells { uint solid_flags[]; };

uniform ivec3 cells;
uniform uint open_faces;

bool isSolidCell(ivec3 c) { return solid_flags[c.x + cells.x * (c.y + cells.y * c.z)] != 0u; }

bool isOpenFace(int axis, int side) { return (open_faces & (1u << uint(2 * axis + side))) != 0u; }

// The face of axis `axis` with lattice index `upper`, between cells
// upper − e_axis and upper: its velocity is prescribed (zero) on a closed
// wall or next to a solid cell.
bool faceIsFixed(int axis, ivec3 upper) {
    ivec3 lower = upper;
    lower[axis] -= 1;
    if (lower[axis] < 0) return !isOpenFace(axis, 0) || isSolidCell(upper);
    if (upper[axis] >= cells[axis]) return !isOpenFace(axis, 1) || isSolidCell(lower);
    return isSolidCell(lower) || isSolidCell(upper);
}
