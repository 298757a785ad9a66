#include "sim/gpu/GpuPressureSolver.h"

#include "sim/gpu/GpuDomain.h"

#include "bridge/core/Error.h"
#include "bridge/layout/GpuLayouts.h"
#include "gl/ShaderLibrary.h"
#include "sim/gpu/GpuDispatch.h"

#include <cstdint>
#include <vector>

namespace eikon::sim::gpu {

namespace {

void barrier() { glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT); }

}  // namespace

GpuPressureSolver::GpuPressureSolver(const FluidDomain& domain, glm::dvec3 h)
    : cells_(domain.cells),
      h_(h),
      openFaces_(openFaceBits(domain)),
      singular_(!domain.anyOpenFace()),
      multigrid_(domain.cells, h, domain.fluidCells(), domain.openFaces().data()),
      cg_(multigrid_.fineOperator()),
      solid_(solidCellFlags(domain)),
      rhs_(multigrid_.fineOperator().newVector("pressure right-hand side", sizeof(double))),
      solution_(multigrid_.fineOperator().newVector("pressure", sizeof(double))),
      divergence_(gl::compileComputeProgram("sim/pressure_divergence.comp")),
      gradient_(gl::compileComputeProgram("sim/pressure_gradient.comp")),
      widen_(gl::compileComputeProgram("sim/vector_convert.comp", {{"CONVERT", "CONVERT_WIDEN"}})) {}

void GpuPressureSolver::setInitialGuess(const GpuField& pressure) {
    EIKON_CHECK(pressure.size() == cells_ && pressure.reference() == 0.0);
    solution_.bindStorage(layout::kSolverVectorX);
    pressure.bind(layout::kSolverField);
    glProgramUniform1ui(widen_.id(), widen_.uniform("count"), static_cast<GLuint>(pressure.count()));
    dispatchOverEntries(widen_, pressure.count());
    barrier();
}

SolveStats GpuPressureSolver::project(std::array<GpuField, 3>& velocity, GpuField& pressure, double tolerance,
                                      int maxIterations) {
    for (int axis = 0; axis < 3; ++axis) {
        glm::ivec3 faces = cells_;
        faces[axis] += 1;
        EIKON_CHECK(velocity[static_cast<std::size_t>(axis)].size() == faces);
    }
    EIKON_CHECK(pressure.size() == cells_);
    const GpuStencilOperator& a = multigrid_.fineOperator();

    // b = −∇·u* on the unknowns
    velocity[0].bind(layout::kSolverVelocityX);
    velocity[1].bind(layout::kSolverVelocityY);
    velocity[2].bind(layout::kSolverVelocityZ);
    a.bindCells();
    rhs_.bindStorage(layout::kSolverVectorB);
    glProgramUniform3i(divergence_.id(), divergence_.uniform("size"), cells_.x, cells_.y, cells_.z);
    glProgramUniform3d(divergence_.id(), divergence_.uniform("h"), h_.x, h_.y, h_.z);
    a.dispatchOverCells(divergence_);
    barrier();
    if (singular_) cg_.removeMeanOverUnknowns(a, rhs_);  // closed box: Σ∇·u = 0 up to rounding

    const SolveStats stats = cg_.solve(
        a, rhs_, solution_, [this](const gl::Buffer& r, const gl::Buffer& z) { multigrid_.apply(r, z); }, tolerance,
        maxIterations, singular_);

    // u −= ∇p on the free faces, 0 on the fixed ones; the float32 pressure.
    velocity[0].bind(layout::kSolverVelocityX);
    velocity[1].bind(layout::kSolverVelocityY);
    velocity[2].bind(layout::kSolverVelocityZ);
    solid_.bindStorage(layout::kSolverCells);
    solution_.bindStorage(layout::kSolverVectorX);
    pressure.bind(layout::kSolverTarget);
    const glm::dvec3 inverseH = 1.0 / h_;
    glProgramUniform3i(gradient_.id(), gradient_.uniform("size"), cells_.x, cells_.y, cells_.z);
    glProgramUniform3d(gradient_.id(), gradient_.uniform("inverseH"), inverseH.x, inverseH.y, inverseH.z);
    glProgramUniform1ui(gradient_.id(), gradient_.uniform("openFaces"), openFaces_);
    gradient_.dispatchOverCells(cells_ + glm::ivec3(1));
    barrier();
    return stats;
}

}  // namespace eikon::sim::gpu
