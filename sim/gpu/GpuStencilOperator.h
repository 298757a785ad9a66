// A SevenPointOperator (sim/fluid/StencilOperator.h) on the GPU: its
// lattice, its weights and one uint of flags per cell — the coupled
// neighbours and the diagonal class, which fix the matrix with the weights
// (the encoding is shaders/sim/seven_point.glsl's). Built from the CPU
// operator, so both sides solve the same matrix: the Poisson matrix of
// [Bridson15] §5.3 or the backward-Euler diffusion matrix I + Δt·D·L.
// The passes that apply it belong to the solvers that use it
// (GpuConjugateGradient, GpuMultigrid, GpuDiffusion); this class gives them
// its uniforms, its flags and the shapes of their dispatches.
#pragma once

#include "gl/GlObjects.h"
#include "sim/fluid/StencilOperator.h"

#include <string>

namespace eikon::sim::gpu {

class GpuStencilOperator {
public:
    GpuStencilOperator() = default;
    // `what` names it in GPU-memory errors.
    GpuStencilOperator(const SevenPointOperator& op, const std::string& what);

    glm::ivec3 size() const { return size_; }
    std::size_t cellCount() const { return static_cast<std::size_t>(size_.x) * size_.y * size_.z; }
    std::size_t unknownCount() const { return unknownCount_; }
    glm::dvec3 weight() const { return weight_; }
    void setWeight(glm::dvec3 weight) { weight_ = weight; }

    // The flags at kSolverCells.
    void bindCells() const;
    // Sets the uniforms size, weight and identity (shaders/sim/seven_point.glsl).
    void setUniforms(const gl::Program& program) const;
    // One invocation per cell.
    void dispatchOverCells(const gl::Program& program) const;
    // One invocation per pair of cells (2i, 2i + 1) along x: a red–black half-sweep.
    void dispatchOverPairs(const gl::Program& program) const;
    // A vector of this lattice, zeroed, of elementBytes per cell.
    gl::Buffer newVector(const std::string& what, std::size_t elementBytes) const;

private:
    glm::ivec3 size_{0};
    glm::dvec3 weight_{0.0};
    double identity_ = 0.0;
    std::size_t unknownCount_ = 0;
    std::string what_;
    gl::Buffer cells_;
};

}  // namespace eikon::sim::gpu
