#include "sim/gpu/GpuReduction.h"

#include "bridge/core/Error.h"
#include "bridge/layout/GpuLayouts.h"
#include "gl/ShaderLibrary.h"

#include <string>

namespace eikon::sim::gpu {

GpuReduction::GpuReduction()
    : partials_(kGroups * sizeof(double), gl::GpuResource{"sim", "the solver's reduction partials"}),
      results_(kSlots * sizeof(double), gl::GpuResource{"sim", "the solver's reduction results"}) {
    results_.clearToZero();
}

const gl::Program& GpuReduction::program(Operation operation, Element element, int pass) {
    gl::Program& program =
        programs_[static_cast<std::size_t>(operation)][static_cast<std::size_t>(element)][static_cast<std::size_t>(pass)];
    if (program.id() == 0) {
        const char* const operations[] = {"REDUCE_SUM", "REDUCE_MAX_ABS", "REDUCE_DOT"};
        program = gl::compileComputeProgram(
            "sim/reduce.comp", {{"OPERATION", operations[static_cast<int>(operation)]},
                                {"ELEMENT", element == Element::Float ? "float" : "double"},
                                {"PASS", std::to_string(pass)}});
    }
    return program;
}

void GpuReduction::run(Operation operation, Element element, const gl::Buffer& a, std::size_t count, int slot,
                       const gl::Buffer* b) {
    EIKON_CHECK(slot >= 0 && slot < kSlots);
    EIKON_CHECK(operation != Operation::Dot || b != nullptr);
    EIKON_CHECK(count <= 0xffffffffu);
    a.bindStorage(layout::kSolverSource);
    (b ? *b : a).bindStorage(layout::kSolverTarget);
    partials_.bindStorage(layout::kSolverPartials);
    results_.bindStorage(layout::kSolverResults);

    const gl::Program& first = program(operation, element, 0);
    first.use();
    glUniform1ui(first.uniform("count"), static_cast<GLuint>(count));
    first.dispatchGroups(kGroups);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    const gl::Program& second = program(operation, element, 1);
    second.use();
    glUniform1ui(second.uniform("count"), kGroups);
    glUniform1ui(second.uniform("slot"), static_cast<GLuint>(slot));
    second.dispatchGroups(1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

double GpuReduction::read(int slot) const {
    EIKON_CHECK(slot >= 0 && slot < kSlots);
    return results_.downloadAs<double>(static_cast<std::size_t>(slot) * sizeof(double));
}

void GpuReduction::write(int slot, double value) {
    EIKON_CHECK(slot >= 0 && slot < kSlots);
    results_.upload(&value, sizeof value, static_cast<std::size_t>(slot) * sizeof(double));
}

}  // namespace eikon::sim::gpu
