#include "sim/gpu/GpuStencilOperator.h"

#include "bridge/layout/GpuLayouts.h"
#include "shaders/common/cpp_shim.h"
#include "sim/gpu/GpuField.h"

#include <cstdint>
#include <vector>

namespace eikon::sim::gpu {

GpuStencilOperator::GpuStencilOperator(const SevenPointOperator& op, const std::string& what)
    : size_(op.size), weight_(op.weight), identity_(op.identity), what_(what),
      cells_(op.cellCount() * sizeof(std::uint32_t), solverResource(what + " flags", op.size)) {
    std::vector<std::uint32_t> flags(op.cellCount());
    for (std::size_t c = 0; c < flags.size(); ++c) {
        flags[c] = shader::stencilFlags(op.coupled[c], op.diagonalClass[c]);
        if (op.isUnknown(c)) ++unknownCount_;
    }
    cells_.upload(flags.data(), flags.size() * sizeof(std::uint32_t));
}

void GpuStencilOperator::bindCells() const { cells_.bindStorage(layout::kSolverCells); }

void GpuStencilOperator::setUniforms(const gl::Program& program) const {
    glProgramUniform3i(program.id(), program.uniform("size"), size_.x, size_.y, size_.z);
    glProgramUniform3d(program.id(), program.uniform("weight"), weight_.x, weight_.y, weight_.z);
    glProgramUniform1d(program.id(), program.uniform("identity"), identity_);
}

void GpuStencilOperator::dispatchOverCells(const gl::Program& program) const { program.dispatchOverCells(size_); }

void GpuStencilOperator::dispatchOverPairs(const gl::Program& program) const {
    program.dispatchOverCells(glm::ivec3((size_.x + 1) / 2, size_.y, size_.z));
}

gl::Buffer GpuStencilOperator::newVector(const std::string& what, std::size_t elementBytes) const {
    gl::Buffer vector(cellCount() * elementBytes, solverResource(what_ + " " + what, size_));
    vector.clearToZero();
    return vector;
}

}  // namespace eikon::sim::gpu
