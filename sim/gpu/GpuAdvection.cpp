#include "sim/gpu/GpuAdvection.h"

#include "bridge/core/Error.h"
#include "bridge/layout/GpuLayouts.h"
#include "gl/ShaderLibrary.h"
#include "sim/gpu/GpuDispatch.h"

#include <glm/vec4.hpp>

#include <algorithm>

namespace eikon::sim::gpu {

namespace {

glm::ivec3 faceLattice(glm::ivec3 cells, int axis) {
    glm::ivec3 size = cells;
    size[axis] += 1;
    return size;
}

glm::dvec3 faceOffset(int axis) {
    glm::dvec3 offset(0.5);
    offset[axis] = 0.0;
    return offset;
}

std::size_t countOf(glm::ivec3 size) { return static_cast<std::size_t>(size.x) * size.y * size.z; }

// One record per cell centre and per face on the two walls normal to each
// axis (shaders/sim/advection_lattice.glsl).
std::size_t displacementRecords(glm::ivec3 cells) {
    const std::size_t wallFaces = static_cast<std::size_t>(cells.y) * cells.z +
                                  static_cast<std::size_t>(cells.x) * cells.z +
                                  static_cast<std::size_t>(cells.x) * cells.y;
    return countOf(cells) + 2 * wallFaces;
}

// The largest of the four lattices: the per-sample scratch serves each in turn.
std::size_t largestLattice(glm::ivec3 cells) {
    std::size_t largest = countOf(cells);
    for (int axis = 0; axis < 3; ++axis) largest = std::max(largest, countOf(faceLattice(cells, axis)));
    return largest;
}

}  // namespace

GpuAdvection::GpuAdvection(glm::ivec3 cells, glm::dvec3 h)
    : cells_(cells),
      h_(h),
      backward_(displacementRecords(cells) * sizeof(glm::vec4), solverResource("characteristics over −Δt", cells)),
      forward_(displacementRecords(cells) * sizeof(glm::vec4), solverResource("characteristics over +Δt", cells)),
      predicted_(largestLattice(cells) * sizeof(float), solverResource("advection's predicted field", cells)),
      low_(largestLattice(cells) * sizeof(float), solverResource("advection's lower bounds", cells)),
      high_(largestLattice(cells) * sizeof(float), solverResource("advection's upper bounds", cells)),
      trace_(gl::compileComputeProgram("sim/advection_trace.comp")),
      predict_(gl::compileComputeProgram("sim/advection_predict.comp")),
      correct_(gl::compileComputeProgram("sim/advection_correct.comp")) {
    EIKON_CHECK(cells.x > 0 && cells.y > 0 && cells.z > 0);
}

void GpuAdvection::trace(const std::array<GpuField, 3>& velocity, double dt) {
    velocity[0].bind(layout::kSolverVelocityX);
    velocity[1].bind(layout::kSolverVelocityY);
    velocity[2].bind(layout::kSolverVelocityZ);
    backward_.bindStorage(layout::kSolverBackward);
    forward_.bindStorage(layout::kSolverForward);
    trace_.use();
    glUniform3i(trace_.uniform("cells"), cells_.x, cells_.y, cells_.z);
    glUniform3f(trace_.uniform("cellsPerMetre"), static_cast<float>(1.0 / h_.x), static_cast<float>(1.0 / h_.y),
                static_cast<float>(1.0 / h_.z));
    glUniform1f(trace_.uniform("dt"), static_cast<float>(dt));
    dispatchOverEntries(trace_, displacementRecords(cells_));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void GpuAdvection::advectField(GpuField& field, int axis) {
    const glm::ivec3 size = field.size();
    // Both passes cover the field's lattice, `axis` naming it.
    auto runOverLattice = [&](const gl::Program& pass) {
        glUniform3i(pass.uniform("cells"), cells_.x, cells_.y, cells_.z);
        glUniform3i(pass.uniform("size"), size.x, size.y, size.z);
        glUniform1i(pass.uniform("axis"), axis);
        pass.dispatchOverCells(size);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    };
    low_.bindStorage(layout::kSolverBoundsLow);
    high_.bindStorage(layout::kSolverBoundsHigh);

    predict_.use();
    field.bind(layout::kSolverSource);
    predicted_.bindStorage(layout::kSolverTarget);
    backward_.bindStorage(layout::kSolverBackward);
    runOverLattice(predict_);

    correct_.use();
    field.bind(layout::kSolverField);
    predicted_.bindStorage(layout::kSolverSource);
    forward_.bindStorage(layout::kSolverForward);
    runOverLattice(correct_);
}

void GpuAdvection::advect(std::array<GpuField, 3>& velocity, const std::vector<GpuField*>& scalars, double dt) {
    for (int axis = 0; axis < 3; ++axis)
        EIKON_CHECK(velocity[axis].size() == faceLattice(cells_, axis) && velocity[axis].offset() == faceOffset(axis));
    for (const GpuField* field : scalars) EIKON_CHECK(field->size() == cells_ && field->offset() == glm::dvec3(0.5));

    // Every characteristic is traced before any field changes, so the
    // velocity components are then advected in place, each from its own
    // start values, through the start-of-step flow.
    trace(velocity, dt);
    for (GpuField* field : scalars) advectField(*field, -1);
    for (int axis = 0; axis < 3; ++axis) advectField(velocity[axis], axis);
}

}  // namespace eikon::sim::gpu
