#include "sim/gpu/GpuMassCorrection.h"

#include "bridge/core/Error.h"
#include "bridge/layout/GpuLayouts.h"
#include "gl/ShaderLibrary.h"
#include "sim/gpu/GpuDispatch.h"

#include <string>

namespace eikon::sim::gpu {

GpuMassCorrection::GpuMassCorrection(std::size_t maxCount)
    : maxCount_(maxCount),
      partials_(3 * kGroups * sizeof(double), gl::GpuResource{"sim", "the mass correction's partials"}),
      budgets_(4 * maxCount * sizeof(double), gl::GpuResource{"sim", "the mass correction's budgets"}) {
    EIKON_CHECK(maxCount > 0);
    budgets_.clearToZero();
}

const gl::Program& GpuMassCorrection::program(Stage stage, int pass) {
    gl::Program& program = programs_[static_cast<std::size_t>(stage)][static_cast<std::size_t>(pass)];
    if (program.id() == 0) {
        const char* const stages[] = {"STAGE_RECORD", "STAGE_MEASURE", "STAGE_RESTORE"};
        program = gl::compileComputeProgram("sim/mass_correction.comp",
                                            {{"STAGE", stages[stage]}, {"PASS", std::to_string(pass)}});
    }
    return program;
}

void GpuMassCorrection::reduce(Stage stage, const GpuField& field, std::size_t budget) {
    EIKON_CHECK(field.count() > 0 && field.count() <= 0xffffffffu);
    field.bind(layout::kSolverField);
    partials_.bindStorage(layout::kSolverPartials);
    budgets_.bindStorage(layout::kSolverResults);

    const gl::Program& first = program(stage, 0);
    first.use();
    glUniform1ui(first.uniform("count"), static_cast<GLuint>(field.count()));
    // Record's first pass reads no budget; the others read low and high.
    if (stage != Record) glUniform1ui(first.uniform("field"), static_cast<GLuint>(budget));
    first.dispatchGroups(kGroups);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    const gl::Program& second = program(stage, 1);
    second.use();
    glUniform1ui(second.uniform("count"), kGroups);
    glUniform1ui(second.uniform("field"), static_cast<GLuint>(budget));
    second.dispatchGroups(1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void GpuMassCorrection::recordBudgets(const std::vector<GpuField*>& fields) {
    EIKON_CHECK(fields.size() <= maxCount_);
    for (std::size_t f = 0; f < fields.size(); ++f) reduce(Record, *fields[f], f);
}

void GpuMassCorrection::restore(const std::vector<GpuField*>& fields) {
    EIKON_CHECK(fields.size() <= maxCount_);
    for (std::size_t f = 0; f < fields.size(); ++f) {
        reduce(Measure, *fields[f], f);
        const gl::Program& apply = program(Restore, 0);
        apply.use();
        fields[f]->bind(layout::kSolverField);
        budgets_.bindStorage(layout::kSolverResults);
        glUniform1ui(apply.uniform("count"), static_cast<GLuint>(fields[f]->count()));
        glUniform1ui(apply.uniform("field"), static_cast<GLuint>(f));
        dispatchOverEntries(apply, fields[f]->count());
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
}

}  // namespace eikon::sim::gpu
