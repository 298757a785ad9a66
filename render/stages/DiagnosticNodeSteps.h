// Where a diagnostic's ray may take longer steps: the nodes of an octree
// ([Sun08] §4.2, as the view's step structure) in which the traced medium is
// nearly uniform. There a ray steps to the node's far face, in whole steps
// of `render.step_voxels` so that its later steps fall where the uniform
// march puts them, and the leapfrog still samples ∇n at each end of its
// step: only the step is longer, nothing is skipped.
#pragma once

#include "render/stages/VaryingVoxels.h"

#include <vector>

namespace eikon::render {

// Per brick of `bricks` (x fastest), the octree level (a node's edge is
// 2^level voxels; a brick is level 2) of the largest node around it, up to
// the one that holds the whole grid, in which δn varies by at most `epsilon` of the whole
// field's δn range and κ not at all, over the node grown by `reachVoxels`
// on every side (the voxels the smoothing, the central differences and the
// trilinear filter bring into it); 0 where even its brick is not. `epsilon`
// is the view's `tracer.epsilon`, the same fraction of the same range.
std::vector<float> nearlyUniformNodeLevels(const BrickRanges& bricks, double reachVoxels, double epsilon);

}  // namespace eikon::render
