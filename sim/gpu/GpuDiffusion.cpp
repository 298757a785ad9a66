#include "sim/gpu/GpuDiffusion.h"

#include "bridge/core/Error.h"
#include "bridge/layout/GpuLayouts.h"
#include "gl/ShaderLibrary.h"
#include "sim/gpu/GpuDispatch.h"

#include <cstdint>

namespace eikon::sim::gpu {

namespace {

constexpr int kNormSlot = 0;  // max|b|, then the largest residual of a sweep

void barrier() { glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT); }

}  // namespace

GpuDiffusion::GpuDiffusion(glm::ivec3 size, const std::vector<DiffusionRole>& roles)
    : a_(diffusionOperator(size, roles), "diffusion"),
      reduction_(std::make_unique<GpuReduction>()),
      rhs_(a_.newVector("diffusion right-hand side", sizeof(double))),
      increment_(a_.newVector("diffusion increment", sizeof(double))),
      rhsPass_(gl::compileComputeProgram("sim/diffusion_rhs.comp")),
      gaussSeidel_(gl::compileComputeProgram("sim/stencil_relax.comp",
                                             {{"RELAX", "RELAX_GAUSS_SEIDEL"}, {"REAL", "double"}})),
      jacobi_(gl::compileComputeProgram("sim/stencil_apply.comp",
                                        {{"OPERATION", "OPERATION_INVERSE_DIAGONAL"}, {"REAL", "double"}})),
      addIncrement_(gl::compileComputeProgram("sim/vector_convert.comp", {{"CONVERT", "CONVERT_ADD"}})) {
    EIKON_CHECK(roles.size() == a_.cellCount());
}

SolveStats GpuDiffusion::diffuse(GpuField& field, glm::dvec3 h, double dtTimesD, double tolerance,
                                 int maxIterations) {
    bytesReadBack_ = 0;
    if (dtTimesD <= 0.0) return {};
    EIKON_CHECK(field.size() == a_.size());
    const glm::dvec3 w = dtTimesD / (h * h);
    a_.setWeight(w);

    // b = −Σ w (φ_c − φ_n): (Δt D ∇²φ)_c
    field.bind(layout::kSolverField);
    a_.bindCells();
    rhs_.bindStorage(layout::kSolverVectorB);
    const glm::ivec3 size = a_.size();
    glProgramUniform3i(rhsPass_.id(), rhsPass_.uniform("size"), size.x, size.y, size.z);
    glProgramUniform3d(rhsPass_.id(), rhsPass_.uniform("weight"), w.x, w.y, w.z);
    a_.dispatchOverCells(rhsPass_);
    barrier();

    // Jacobi contracts the error by ρ <= 2Σw / (1 + 2Σw) per sweep and
    // red–black Gauss–Seidel by about ρ²; below kGaussSeidelBelow that
    // reaches the tolerance in fewer bytes moved than CG.
    const double coupling = 2.0 * (w.x + w.y + w.z);
    SolveStats stats;
    if (coupling / (1.0 + coupling) <= kGaussSeidelBelow) {
        stats = gaussSeidel(tolerance, maxIterations);
    } else {
        if (!cg_) cg_ = std::make_unique<GpuConjugateGradient>(a_);
        increment_.clearToZero();
        stats = cg_->solve(
            a_, rhs_, increment_, [this](const gl::Buffer& r, const gl::Buffer& z) { jacobi(r, z); }, tolerance,
            maxIterations, false);
        bytesReadBack_ = cg_->bytesReadBack();
    }
    // No iteration: max|b| = 0 or the initial residual already small enough, and δ = 0.
    if (stats.iterations == 0) return stats;
    increment_.bindStorage(layout::kSolverVectorX);
    field.bind(layout::kSolverField);
    glProgramUniform1ui(addIncrement_.id(), addIncrement_.uniform("count"), static_cast<GLuint>(a_.cellCount()));
    dispatchOverEntries(addIncrement_, a_.cellCount());
    barrier();
    return stats;
}

void GpuDiffusion::jacobi(const gl::Buffer& r, const gl::Buffer& z) {
    a_.bindCells();
    r.bindStorage(layout::kSolverVectorR);
    z.bindStorage(layout::kSolverVectorQ);
    a_.setUniforms(jacobi_);
    a_.dispatchOverCells(jacobi_);
}

void GpuDiffusion::relax(int colour, bool fromZero) {
    a_.bindCells();
    rhs_.bindStorage(layout::kSolverVectorB);
    increment_.bindStorage(layout::kSolverVectorX);
    residual_.bindStorage(layout::kSolverVectorR);
    a_.setUniforms(gaussSeidel_);
    glProgramUniform1i(gaussSeidel_.id(), gaussSeidel_.uniform("colour"), colour);
    glProgramUniform1i(gaussSeidel_.id(), gaussSeidel_.uniform("fromZero"), fromZero ? 1 : 0);
    a_.dispatchOverPairs(gaussSeidel_);
    barrier();
}

SolveStats GpuDiffusion::gaussSeidel(double tolerance, int maxIterations) {
    const std::size_t n = a_.cellCount();
    using Operation = GpuReduction::Operation;
    using Element = GpuReduction::Element;
    reduction_->run(Operation::MaxAbs, Element::Double, rhs_, n, kNormSlot);
    const double bNorm = reduction_->read(kNormSlot);
    bytesReadBack_ += sizeof(double);
    if (bNorm == 0.0) return {};
    if (residual_.bytes() == 0) residual_ = a_.newVector("diffusion residual", sizeof(double));
    // Each sweep meets colour 0's residuals before their update and colour
    // 1's after colour 0's; their largest is the sweep's stopping test.
    SolveStats stats;
    while (stats.iterations < maxIterations) {
        relax(0, stats.iterations == 0);
        relax(1, false);
        reduction_->run(Operation::MaxAbs, Element::Double, residual_, n, kNormSlot);
        ++stats.iterations;
        stats.relativeResidual = reduction_->read(kNormSlot) / bNorm;
        bytesReadBack_ += sizeof(double);
        if (stats.relativeResidual <= tolerance) break;
    }
    return stats;
}

}  // namespace eikon::sim::gpu
