// The fluid domain (sim/fluid/Boundaries.h) as the GPU passes read it:
// shaders/sim/fluid_domain.glsl's solid flags and open-face bits.
#pragma once

#include "gl/GlObjects.h"
#include "sim/fluid/Boundaries.h"

namespace eikon::sim::gpu {

// One uint per cell, 1 = solid.
gl::Buffer solidCellFlags(const FluidDomain& domain);
// Bit faceIndex(axis, side) set where that face of the box is open.
GLuint openFaceBits(const FluidDomain& domain);

}  // namespace eikon::sim::gpu
