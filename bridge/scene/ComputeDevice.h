// Where a simulation (sim.device) or the renderer's grid passes
// (render.device) run: the CPU (TBB) or the GPU (OpenGL compute passes,
// sim/gpu, render/stages). `auto` takes the GPU where the renderer's OpenGL
// context is a hardware GPU and the CPU under a software rasterizer, where
// the CPU code measured faster (docs/benchmarks-gpu-solver.md,
// docs/benchmarks-cpu.md).
#pragma once

namespace eikon {

enum class ComputeDevice { Auto, Cpu, Gpu };

inline bool runsOnGpu(ComputeDevice device, bool hardwareGpu) {
    return device == ComputeDevice::Gpu || (device == ComputeDevice::Auto && hardwareGpu);
}

}  // namespace eikon
