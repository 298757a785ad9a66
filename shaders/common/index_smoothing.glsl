// One axis of the separable Gaussian that smooths δn before its gradient is
// taken ([Sun08] §4.1: σ = window/6, 9³ by default), at one cell: samples
// past the grid take the edge value. Written once for both backends: the
// compute shader smooth_index.comp and the native loop
// (render/stages/NativePrepare.cpp) call it. The includer gives
//     float smoothing_source(ivec3 cell)  // δn before this pass, cell inside the grid
//     float smoothing_weight(int offset)  // weights[|offset|]; the whole kernel sums to one

float smoothed_along_axis(ivec3 cell, ivec3 cells, ivec3 axis, int radius) {
    float sum = smoothing_weight(0) * smoothing_source(cell);
    for (int offset = 1; offset <= radius; ++offset) {
        ivec3 before = clamp(cell - offset * axis, ivec3(0), cells - 1);
        ivec3 after = clamp(cell + offset * axis, ivec3(0), cells - 1);
        sum += smoothing_weight(offset) * (smoothing_source(before) + smoothing_source(after));
    }
    return sum;
}
