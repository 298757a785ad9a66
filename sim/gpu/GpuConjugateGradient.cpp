#include "sim/gpu/GpuConjugateGradient.h"

#include "bridge/core/Error.h"
#include "bridge/layout/GpuLayouts.h"
#include "gl/ShaderLibrary.h"
#include "sim/gpu/GpuDispatch.h"

#include <array>

namespace eikon::sim::gpu {

namespace {

using Operation = GpuReduction::Operation;
using Element = GpuReduction::Element;

void barrier() { glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT); }

gl::Program update(const char* which) { return gl::compileComputeProgram("sim/cg_update.comp", {{"UPDATE", which}}); }

}  // namespace

GpuConjugateGradient::GpuConjugateGradient(const GpuStencilOperator& shape)
    : r_(shape.newVector("CG residual", sizeof(double))),
      p_(shape.newVector("CG search direction", sizeof(double))),
      q_(shape.newVector("CG A·p", sizeof(double))),
      apply_(gl::compileComputeProgram("sim/stencil_apply.comp",
                                       {{"OPERATION", "OPERATION_APPLY"}, {"REAL", "double"}})),
      residual_(gl::compileComputeProgram("sim/stencil_apply.comp",
                                          {{"OPERATION", "OPERATION_RESIDUAL"}, {"REAL", "double"}})),
      step_(update("UPDATE_STEP")),
      direction_(update("UPDATE_DIRECTION")),
      removeMean_(update("UPDATE_REMOVE_MEAN")) {}

void GpuConjugateGradient::removeMeanOverUnknowns(const GpuStencilOperator& a, const gl::Buffer& values) {
    if (a.unknownCount() == 0) return;
    reduction_.run(Operation::Sum, Element::Double, values, a.cellCount(), kSum);
    a.bindCells();
    values.bindStorage(layout::kSolverVectorR);
    reduction_.bindResults(layout::kSolverResults);
    glProgramUniform1ui(removeMean_.id(), removeMean_.uniform("sumSlot"), kSum);
    glProgramUniform1ui(removeMean_.id(), removeMean_.uniform("unknowns"), static_cast<GLuint>(a.unknownCount()));
    glProgramUniform1ui(removeMean_.id(), removeMean_.uniform("count"), static_cast<GLuint>(a.cellCount()));
    dispatchOverEntries(removeMean_, a.cellCount());
    barrier();
}

void GpuConjugateGradient::precondition(const GpuStencilOperator& a, const Preconditioner& preconditioner,
                                        bool singular, int rhoSlot) {
    preconditioner(r_, q_);
    barrier();
    if (singular) removeMeanOverUnknowns(a, q_);
    reduction_.run(Operation::Dot, Element::Double, r_, a.cellCount(), rhoSlot, &q_);
}

double GpuConjugateGradient::readResidualNorm() {
    bytesReadBack_ += sizeof(double);
    return reduction_.read(kResidualNorm);
}

SolveStats GpuConjugateGradient::solve(const GpuStencilOperator& a, const gl::Buffer& b, gl::Buffer& x,
                                       const Preconditioner& preconditioner, double tolerance, int maxIterations,
                                       bool singular) {
    const std::size_t n = a.cellCount();
    EIKON_CHECK(r_.bytes() == n * sizeof(double) && b.bytes() == r_.bytes() && x.bytes() == r_.bytes());
    bytesReadBack_ = 0;
    const GLuint count = static_cast<GLuint>(n);

    // r = b − A x, and max|b| and max|r| in one read.
    a.bindCells();
    x.bindStorage(layout::kSolverVectorX);
    b.bindStorage(layout::kSolverVectorB);
    r_.bindStorage(layout::kSolverVectorR);
    a.setUniforms(residual_);
    glProgramUniform1i(residual_.id(), residual_.uniform("colour"), -1);
    a.dispatchOverCells(residual_);
    barrier();
    if (singular) removeMeanOverUnknowns(a, r_);
    reduction_.run(Operation::MaxAbs, Element::Double, b, n, kRightHandSideNorm);
    reduction_.run(Operation::MaxAbs, Element::Double, r_, n, kResidualNorm);
    std::array<double, 2> norms{};
    static_assert(kResidualNorm == kRightHandSideNorm + 1);
    reduction_.results().download(norms.data(), sizeof norms, kRightHandSideNorm * sizeof(double));
    bytesReadBack_ += sizeof norms;
    const double bNorm = norms[0];
    if (bNorm == 0.0) {
        x.clearToZero();
        return {};
    }
    SolveStats stats{0, norms[1] / bNorm};
    if (stats.relativeResidual <= tolerance) return stats;

    int rho = kRho;
    precondition(a, preconditioner, singular, rho);
    p_.copyFrom(q_);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    glProgramUniform1ui(step_.id(), step_.uniform("curvatureSlot"), kCurvature);
    glProgramUniform1ui(step_.id(), step_.uniform("count"), count);
    glProgramUniform1ui(direction_.id(), direction_.uniform("count"), count);
    while (stats.iterations < maxIterations) {
        // q = A p and p · q
        a.bindCells();
        p_.bindStorage(layout::kSolverVectorP);
        q_.bindStorage(layout::kSolverVectorQ);
        a.setUniforms(apply_);
        a.dispatchOverCells(apply_);
        barrier();
        reduction_.run(Operation::Dot, Element::Double, p_, n, kCurvature, &q_);

        // x += α p, r −= α q with α = ρ / (p · q)
        x.bindStorage(layout::kSolverVectorX);
        r_.bindStorage(layout::kSolverVectorR);
        p_.bindStorage(layout::kSolverVectorP);
        q_.bindStorage(layout::kSolverVectorQ);
        reduction_.bindResults(layout::kSolverResults);
        glProgramUniform1ui(step_.id(), step_.uniform("rhoSlot"), static_cast<GLuint>(rho));
        dispatchOverEntries(step_, n);
        barrier();
        reduction_.run(Operation::MaxAbs, Element::Double, r_, n, kResidualNorm);
        ++stats.iterations;
        stats.relativeResidual = readResidualNorm() / bNorm;
        if (stats.relativeResidual <= tolerance) break;

        // z = M r, ρ' = r · z, and p = z + (ρ' / ρ) p
        const int nextRho = rho == kRho ? kRho + 1 : kRho;
        precondition(a, preconditioner, singular, nextRho);
        p_.bindStorage(layout::kSolverVectorP);
        q_.bindStorage(layout::kSolverVectorQ);
        reduction_.bindResults(layout::kSolverResults);
        glProgramUniform1ui(direction_.id(), direction_.uniform("rhoSlot"), static_cast<GLuint>(rho));
        glProgramUniform1ui(direction_.id(), direction_.uniform("nextRhoSlot"), static_cast<GLuint>(nextRho));
        dispatchOverEntries(direction_, n);
        barrier();
        rho = nextRho;
    }
    return stats;
}

}  // namespace eikon::sim::gpu
