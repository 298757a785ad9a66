// (∇n, δn) at one cell: ∇n by central differences of δn between cell
// centres, one-sided at the grid faces, so the tracers fetch both with one
// trilinear lookup. Written once for both backends: the compute shader
// prepare_gradient.comp and the native loop (render/stages/NativePrepare.cpp)
// call it. The includer gives
//     float gradient_source(ivec3 cell)  // smoothed δn, cell inside the grid

float central_difference(ivec3 cell, ivec3 axis, ivec3 cells, float h) {
    ivec3 lo = max(cell - axis, ivec3(0));
    ivec3 hi = min(cell + axis, cells - 1);
    ivec3 reach = hi - lo;  // along `axis` only
    float span = float(reach.x + reach.y + reach.z);
    return span > 0.0f ? (gradient_source(hi) - gradient_source(lo)) / (span * h) : 0.0f;
}

vec4 gradient_and_index(ivec3 cell, ivec3 cells, vec3 h) {
    vec3 gradient = vec3(central_difference(cell, ivec3(1, 0, 0), cells, h.x),
                         central_difference(cell, ivec3(0, 1, 0), cells, h.y),
                         central_difference(cell, ivec3(0, 0, 1), cells, h.z));
    return vec4(gradient, gradient_source(cell));
}
