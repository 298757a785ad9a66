#include "sim/gpu/GpuMultigrid.h"

#include "sim/fluid/Multigrid.h"

#include "bridge/core/Error.h"
#include "bridge/layout/GpuLayouts.h"
#include "gl/ShaderLibrary.h"
#include "sim/gpu/GpuDispatch.h"

#include <algorithm>
#include <string>

namespace eikon::sim::gpu {

namespace {

// The coarsest level has every axis under kMinCoarsenSize: one work group of
// the coarsest-level pass covers it.
constexpr std::size_t kMostCoarsestCells = 27;

void barrier() { glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT); }

gl::Program relaxProgram(const char* mode) {
    return gl::compileComputeProgram("sim/stencil_relax.comp", {{"RELAX", mode}, {"REAL", "float"}});
}

gl::Program transferProgram(const char* which) {
    return gl::compileComputeProgram("sim/multigrid_transfer.comp", {{"TRANSFER", which}});
}

gl::Program convertProgram(const char* which) {
    return gl::compileComputeProgram("sim/vector_convert.comp", {{"CONVERT", which}});
}

void setTransferUniforms(const gl::Program& program, glm::ivec3 fine, glm::ivec3 coarse, glm::ivec3 coarsened) {
    glProgramUniform3i(program.id(), program.uniform("fineSize"), fine.x, fine.y, fine.z);
    glProgramUniform3i(program.id(), program.uniform("coarseSize"), coarse.x, coarse.y, coarse.z);
    glProgramUniform3i(program.id(), program.uniform("coarsened"), coarsened.x, coarsened.y, coarsened.z);
}

}  // namespace

GpuMultigrid::GpuMultigrid(glm::ivec3 size, glm::dvec3 h, const std::vector<std::uint8_t>& active,
                           const bool openFaces[6])
    : smooth_(relaxProgram("RELAX_SMOOTH")),
      residual_(gl::compileComputeProgram("sim/stencil_apply.comp",
                                          {{"OPERATION", "OPERATION_RESIDUAL"}, {"REAL", "float"}})),
      coarsest_(relaxProgram("RELAX_COARSEST")),
      restrict_(transferProgram("TRANSFER_RESTRICT")),
      prolong_(transferProgram("TRANSFER_PROLONG")),
      narrow_(convertProgram("CONVERT_NARROW")),
      widen_(convertProgram("CONVERT_WIDEN")) {
    std::vector<std::uint8_t> levelActive = active;
    while (true) {
        const SevenPointOperator op = poissonOperator(size, h, levelActive, openFaces);
        Level level;
        level.op = GpuStencilOperator(op, "multigrid level " + std::to_string(levels_.size()));
        level.x = level.op.newVector("unknowns", sizeof(float));
        level.b = level.op.newVector("right-hand side", sizeof(float));
        for (int axis = 0; axis < 3; ++axis) level.coarsened[axis] = size[axis] >= kMinCoarsenSize ? 1 : 0;
        if (level.coarsened == glm::ivec3(0)) {
            EIKON_CHECK(level.op.cellCount() <= kMostCoarsestCells);
            levels_.push_back(std::move(level));
            return;
        }
        level.r = level.op.newVector("residual", sizeof(float));
        glm::ivec3 coarseSize = size;
        for (int axis = 0; axis < 3; ++axis)
            if (level.coarsened[axis]) {
                coarseSize[axis] = (size[axis] + 1) / 2;
                h[axis] *= 2.0;
                level.restrictionScale *= 0.5f;
            }
        // A coarse cell is active when any of its children is.
        std::vector<std::uint8_t> coarseActive(static_cast<std::size_t>(coarseSize.x) * coarseSize.y * coarseSize.z, 0);
        for (int k = 0; k < size.z; ++k)
            for (int j = 0; j < size.y; ++j)
                for (int i = 0; i < size.x; ++i) {
                    if (!levelActive[op.index(i, j, k)]) continue;
                    const glm::ivec3 parent = glm::ivec3(i, j, k) / (glm::ivec3(1) + level.coarsened);
                    coarseActive[static_cast<std::size_t>(parent.x) +
                                 static_cast<std::size_t>(coarseSize.x) *
                                     (static_cast<std::size_t>(parent.y) +
                                      static_cast<std::size_t>(coarseSize.y) * static_cast<std::size_t>(parent.z))] = 1;
                }
        levels_.push_back(std::move(level));
        size = coarseSize;
        levelActive = std::move(coarseActive);
    }
}

int GpuMultigrid::dispatchesPerCycle() const {
    // Per level above the coarsest: 4·kSmoothingSweeps half-sweeps, the
    // residual, the restriction and the prolongation; then the coarsest
    // level's single pass, and the conversions into and out of float32.
    return (levelCount() - 1) * (4 * kSmoothingSweeps + 3) + 1 + 2;
}

void GpuMultigrid::apply(const gl::Buffer& r, const gl::Buffer& z) const {
    const Level& fine = levels_.front();
    const std::size_t n = fine.op.cellCount();
    EIKON_CHECK(r.bytes() == n * sizeof(double) && z.bytes() == n * sizeof(double));
    r.bindStorage(layout::kSolverVectorX);
    fine.b.bindStorage(layout::kSolverField);
    glProgramUniform1ui(narrow_.id(), narrow_.uniform("count"), static_cast<GLuint>(n));
    dispatchOverEntries(narrow_, n);
    barrier();
    vcycle(0);
    z.bindStorage(layout::kSolverVectorX);
    fine.x.bindStorage(layout::kSolverField);
    glProgramUniform1ui(widen_.id(), widen_.uniform("count"), static_cast<GLuint>(n));
    dispatchOverEntries(widen_, n);
    barrier();
}

void GpuMultigrid::relax(const Level& level, int colour, bool fromZero) const {
    level.op.bindCells();
    level.b.bindStorage(layout::kSolverVectorB);
    level.x.bindStorage(layout::kSolverVectorX);
    level.op.setUniforms(smooth_);
    glProgramUniform1i(smooth_.id(), smooth_.uniform("colour"), colour);
    glProgramUniform1i(smooth_.id(), smooth_.uniform("fromZero"), fromZero ? 1 : 0);
    level.op.dispatchOverPairs(smooth_);
    barrier();
}

void GpuMultigrid::vcycle(std::size_t l) const {
    const Level& level = levels_[l];
    if (l + 1 == levels_.size()) {
        // Coarsest level: symmetric sweeps from zero, enough to cross it a few times.
        const glm::ivec3 size = level.op.size();
        level.op.bindCells();
        level.b.bindStorage(layout::kSolverVectorB);
        level.x.bindStorage(layout::kSolverVectorX);
        level.op.setUniforms(coarsest_);
        glProgramUniform1i(coarsest_.id(), coarsest_.uniform("sweeps"), 2 * std::max({size.x, size.y, size.z}));
        coarsest_.dispatchGroups(1);  // one work group
        barrier();
        return;
    }
    // Pre-smoothing from x = 0, colours (0, 1) per sweep, then the residual,
    // which the last half-sweep (colour 1) left on colour 0 only.
    for (int sweep = 0; sweep < kSmoothingSweeps; ++sweep) {
        relax(level, 0, sweep == 0);
        relax(level, 1, false);
    }
    level.op.bindCells();
    level.x.bindStorage(layout::kSolverVectorX);
    level.b.bindStorage(layout::kSolverVectorB);
    level.r.bindStorage(layout::kSolverVectorR);
    level.op.setUniforms(residual_);
    glProgramUniform1i(residual_.id(), residual_.uniform("colour"), 0);
    level.op.dispatchOverCells(residual_);
    barrier();

    const Level& coarse = levels_[l + 1];
    restrictResidual(level, coarse);
    vcycle(l + 1);
    prolongAndAdd(coarse, level);
    // Post-smoothing, colours (1, 0) per sweep, so that the cycle is symmetric.
    for (int sweep = 0; sweep < kSmoothingSweeps; ++sweep) {
        relax(level, 1, false);
        relax(level, 0, false);
    }
}

void GpuMultigrid::restrictResidual(const Level& fine, const Level& coarse) const {
    coarse.op.bindCells();
    fine.r.bindStorage(layout::kSolverFine);
    coarse.b.bindStorage(layout::kSolverCoarse);
    setTransferUniforms(restrict_, fine.op.size(), coarse.op.size(), fine.coarsened);
    glProgramUniform1f(restrict_.id(), restrict_.uniform("restrictionScale"), fine.restrictionScale);
    restrict_.dispatchOverCells(coarse.op.size());
    barrier();
}

void GpuMultigrid::prolongAndAdd(const Level& coarse, const Level& fine) const {
    fine.op.bindCells();
    fine.x.bindStorage(layout::kSolverFine);
    coarse.x.bindStorage(layout::kSolverCoarse);
    setTransferUniforms(prolong_, fine.op.size(), coarse.op.size(), fine.coarsened);
    prolong_.dispatchOverCells(fine.op.size());
    barrier();
}

}  // namespace eikon::sim::gpu
