// Where in its pixel each camera ray passes: render.samples_per_pixel = k²
// rays through the centres of a k × k grid of equal cells (stratified
// sampling, Pharr, Jakob & Humphreys, Physically Based Rendering, 3rd ed.,
// §7.3), each standing for its cell — the environment's checkerboard is
// filtered over the cell's footprint (common/environment.glsl) — and the
// pixel is their mean: a box filter over the pixel. k = 1 is the pixel's
// centre, the image of one ray a pixel.
#pragma once

#include <glm/vec2.hpp>

namespace eikon::render {

// k for k² samples a pixel; 0 where `samples` is not a square.
int sampleGridSide(int samples);

// The centre of cell `index` (row by row from the top left) of a k × k grid,
// as a fraction of the pixel, each coordinate in (0, 1); x right, y down.
glm::vec2 gridSampleOffset(int index, int k);

}  // namespace eikon::render
