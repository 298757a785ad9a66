// The vorticity of vorticity confinement ([Fedkiw01] eq. 9) at every cell:
// ω = ∇ × ū, ū the mean of the cell's two faces per axis, by central
// differences over the neighbouring cells, one-sided at the box's edges
// (sim/fluid/VorticityConfinement.cpp). Writes (ω, |ω|) per cell.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(std430, binding = kSolverVelocityX) readonly buffer VelocityX { float u[]; };
layout(std430, binding = kSolverVelocityY) readonly buffer VelocityY { float v[]; };
layout(std430, binding = kSolverVelocityZ) readonly buffer VelocityZ { float w[]; };
layout(std430, binding = kSolverVorticity) writeonly buffer Vorticity { vec4 omega[]; };

uniform ivec3 cells;
uniform vec3 h;  // cell edges, m

// Component `a` of ū at cell c: the mean of its lower and upper face.
float centred(int a, ivec3 c) {
    ivec3 size = cells;
    size[a] += 1;
    ivec3 upper = c;
    upper[a] += 1;
    int lower_index = c.x + size.x * (c.y + size.y * c.z);
    int upper_index = upper.x + size.x * (upper.y + size.y * upper.z);
    if (a == 0) return 0.5 * (u[lower_index] + u[upper_index]);
    if (a == 1) return 0.5 * (v[lower_index] + v[upper_index]);
    return 0.5 * (w[lower_index] + w[upper_index]);
}

// ∂ū_component/∂x_axis at cell c.
float derivative(int component, ivec3 c, int axis) {
    ivec3 low = c;
    ivec3 high = c;
    low[axis] = max(c[axis] - 1, 0);
    high[axis] = min(c[axis] + 1, cells[axis] - 1);
    if (high[axis] == low[axis]) return 0.0;
    return (centred(component, high) - centred(component, low)) / (float(high[axis] - low[axis]) * h[axis]);
}

void main() {
    ivec3 c = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(c, cells))) return;
    vec3 curl = vec3(derivative(2, c, 1) - derivative(1, c, 2), derivative(0, c, 2) - derivative(2, c, 0),
                     derivative(1, c, 0) - derivative(0, c, 1));
    omega[c.x + cells.x * (c.y + cells.y * c.z)] = vec4(curl, length(curl));
}
