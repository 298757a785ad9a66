// Where a grid pass (prepare, step structure) runs: as compute shaders on
// the OpenGL device, or as its kernels — the same shared text of
// shaders/common, compiled as C++ — in native TBB loops, reading its inputs
// from and writing its outputs to the same textures. render.device "auto"
// takes the native loops under a software rasterizer (where they take 2 to
// 5 times less CPU per cell than llvmpipe's, docs/benchmarks-cpu.md) and the
// compute shaders on a GPU, as sim.device does for the solver.
#pragma once

#include "bridge/scene/ComputeDevice.h"
#include "gl/GlObjects.h"

#include <cstddef>

namespace eikon::render {

enum class StageDevice { Gpu, Cpu };

// `requested` resolved against the current OpenGL context's renderer.
StageDevice gridPassDevice(ComputeDevice requested);

// "gpu" or "cpu", as the frame report names it.
const char* stageDeviceName(StageDevice device);

// The native passes' read of an input texture: all of it as floats in
// `format` (GL_RED, GL_RGB, GL_RGBA; x fastest) into `data`, `bytes` long.
void downloadTexels(const gl::Texture3D& texture, GLenum format, void* data, std::size_t bytes);

}  // namespace eikon::render
