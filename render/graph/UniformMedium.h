// The rule by which a frame leaves out the stages a medium does not need
// (docs/architecture.md, "Stages a scene does not need"): a field that holds
// one value in every cell has no gradient, smooths to itself and makes one
// octree node of the whole grid, so FrameRenderer writes the prepared
// gradient (0, 0, 0, δn) and the step structure's one label in closed form
// instead of running the prepare and step_structure stages over every cell,
// and reports them `ran: false` with kUniformIndexReason or
// kUniformMediumReason.
#pragma once

#include "render/stages/FieldTextures.h"

namespace eikon::render {

// True when every cell of `field` (`components` floats a cell) holds the
// same value, or the scene has no such field (it is 0 everywhere); false for
// a field whose values are on the GPU only (a GPU solver's ring), which is
// not read back to find out.
bool holdsOneValue(const FieldSource& field, int components);

inline constexpr const char* kUniformIndexReason =
    "uniform index: δn is the same in every cell, so ∇n = 0 and smoothing changes nothing; "
    "the gradient texture is filled with (0, 0, 0, δn)";
inline constexpr const char* kUniformMediumReason =
    "uniform medium: δn and κ are the same in every cell and nothing glows, so the octree is one node; "
    "its label is filled in";

}  // namespace eikon::render
