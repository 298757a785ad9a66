// The lattices of MacCormack advection ([Selle08] eqs. 3–5) on the GPU,
// shared by the trace, predict and correct passes (sim/gpu/GpuAdvection.h):
// where a sample's characteristic displacement is recorded, and trilinear
// sampling clamped to a lattice exactly as sim/field/GridField.h's
// sampleTrilinear and sampleWithBounds do it. GLSL only.
//
// Displacement records (kSolverBackward, kSolverForward), in cells: first one
// per cell centre, x fastest; then, per axis a, the faces normal to a on the
// two walls of the grid (the faces with one neighbouring cell, which trace
// for themselves): the low wall's, then the high wall's, each over the two
// other axes in increasing order, the first fastest. A face between two cells
// takes the mean of their records (sim/fluid/Advection.cpp, LatticeEnds).

// The two axes across `axis`, in increasing order.
ivec2 axesAcross(int axis) { return axis == 0 ? ivec2(1, 2) : (axis == 1 ? ivec2(0, 2) : ivec2(0, 1)); }

uint cellRecord(ivec3 cell, ivec3 cells) { return uint(cell.x + cells.x * (cell.y + cells.y * cell.z)); }

// The faces normal to `axis` on one wall.
uint wallFaceCount(int axis, ivec3 cells) {
    ivec2 across = axesAcross(axis);
    return uint(cells[across.x] * cells[across.y]);
}

// The first record of the wall faces normal to `axis`.
uint firstWallRecord(int axis, ivec3 cells) {
    uint first = uint(cells.x * cells.y * cells.z);
    for (int a = 0; a < axis; ++a) first += 2u * wallFaceCount(a, cells);
    return first;
}

uint recordCount(ivec3 cells) { return firstWallRecord(3, cells); }

// The record of face `face` (lattice indices) normal to `axis`, on a wall.
uint wallRecord(int axis, ivec3 face, ivec3 cells) {
    ivec2 across = axesAcross(axis);
    uint side = face[axis] == 0 ? 0u : 1u;
    return firstWallRecord(axis, cells) + side * wallFaceCount(axis, cells) +
           uint(face[across.x] + cells[across.x] * face[across.y]);
}

// The two records whose mean is the displacement of sample `ijk` of lattice
// `axis` (−1: cell centres; a: the faces normal to a). Where one record
// serves, both name it: (d + d)/2 is d exactly in floating point.
uvec2 displacementRecords(int axis, ivec3 ijk, ivec3 cells) {
    if (axis < 0) return uvec2(cellRecord(ijk, cells));
    int along = ijk[axis];
    if (along == 0 || along == cells[axis]) return uvec2(wallRecord(axis, ijk, cells));
    ivec3 below = ijk;
    below[axis] -= 1;
    return uvec2(cellRecord(below, cells), cellRecord(ijk, cells));
}

// Trilinear sampling at lattice coordinate whole + fraction, clamped to a
// lattice of `size` samples like GridField.h's detail::locate. The integer
// part stays exact: a point is resolved to float rounding of its fraction
// however large the lattice.
struct AxisCell {
    int lower;  // the lower lattice index
    int step;   // to the next one: 0 on a one-sample axis
    float t;    // the fraction toward it
};

AxisCell locateOnAxis(int whole, float fraction, int n) {
    if (n == 1) return AxisCell(0, 0, 0.0);
    float below = floor(fraction);
    int lower = whole + int(below);
    if (lower < 0) return AxisCell(0, 1, 0.0);
    if (lower >= n - 1) return AxisCell(n - 2, 1, 1.0);
    return AxisCell(lower, 1, fraction - below);
}

struct Stencil {
    uint base;     // the index of the lowest of the eight samples
    uvec3 stride;  // index steps to the next sample along each axis
    vec3 t;        // the fractions along each axis
};

Stencil stencilAt(ivec3 whole, vec3 fraction, ivec3 size) {
    AxisCell x = locateOnAxis(whole.x, fraction.x, size.x);
    AxisCell y = locateOnAxis(whole.y, fraction.y, size.y);
    AxisCell z = locateOnAxis(whole.z, fraction.z, size.z);
    uint base = uint(x.lower) + uint(size.x) * (uint(y.lower) + uint(size.y) * uint(z.lower));
    uvec3 stride = uvec3(x.step, size.x * y.step, size.x * size.y * z.step);
    return Stencil(base, stride, vec3(x.t, y.t, z.t));
}

// Corner n of the eight, x fastest (GridField.h's detail::gather order).
uint cornerIndex(Stencil s, int n) {
    return s.base + ((n & 1) != 0 ? s.stride.x : 0u) + ((n & 2) != 0 ? s.stride.y : 0u) +
           ((n & 4) != 0 ? s.stride.z : 0u);
}

// GridField.h's detail::blend.
float blendCorners(float v[8], vec3 t) {
    float x00 = v[0] + t.x * (v[1] - v[0]);
    float x10 = v[2] + t.x * (v[3] - v[2]);
    float x01 = v[4] + t.x * (v[5] - v[4]);
    float x11 = v[6] + t.x * (v[7] - v[6]);
    float y0 = x00 + t.y * (x10 - x00);
    float y1 = x01 + t.y * (x11 - x01);
    return y0 + t.z * (y1 - y0);
}

uint sampleIndex(ivec3 ijk, ivec3 size) {
    return uint(ijk.x) + uint(size.x) * (uint(ijk.y) + uint(size.y) * uint(ijk.z));
}
