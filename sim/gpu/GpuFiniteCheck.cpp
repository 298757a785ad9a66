#include "sim/gpu/GpuFiniteCheck.h"

#include "bridge/core/Error.h"
#include "bridge/layout/GpuLayouts.h"
#include "gl/ShaderLibrary.h"
#include "sim/gpu/GpuDispatch.h"
#include "sim/fluid/FiniteCheck.h"

#include <array>
#include <bit>

namespace eikon::sim::gpu {

namespace {
constexpr std::uint32_t kAllFinite = 0xffffffffu;
}

GpuFiniteCheck::GpuFiniteCheck()
    : firstBad_(2 * kSlots * sizeof(std::uint32_t), gl::GpuResource{"sim", "the solver's NaN/Inf check"}),
      find_(gl::compileComputeProgram("sim/find_nonfinite.comp", {{"FIND", "1"}})),
      record_(gl::compileComputeProgram("sim/find_nonfinite.comp")) {}

void GpuFiniteCheck::begin() {
    checks_.clear();
    const std::array<std::uint32_t, kSlots> none = [] {
        std::array<std::uint32_t, kSlots> a{};
        a.fill(kAllFinite);
        return a;
    }();
    firstBad_.upload(none.data(), sizeof none);
}

void GpuFiniteCheck::check(const GpuField& field, const std::string& name, const std::string& sample,
                           const SolverPhase& when) {
    EIKON_CHECK(checks_.size() < static_cast<std::size_t>(kSlots));
    field.bind(layout::kSolverField);
    firstBad_.bindStorage(layout::kSolverPartials);
    find_.use();
    glUniform1ui(find_.uniform("count"), static_cast<GLuint>(field.count()));
    glUniform1ui(find_.uniform("slot"), static_cast<GLuint>(checks_.size()));
    dispatchOverEntries(find_, field.count());
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    record_.use();
    glUniform1ui(record_.uniform("count"), static_cast<GLuint>(kSlots));
    glUniform1ui(record_.uniform("slot"), static_cast<GLuint>(checks_.size()));
    record_.dispatchGroups(1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    checks_.push_back({&field, name, sample, when});
}

void GpuFiniteCheck::finish() {
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::array<std::uint32_t, kSlots> first{};
    firstBad_.download(first.data(), checks_.size() * sizeof(std::uint32_t));
    bytesRead_ = checks_.size() * sizeof(std::uint32_t);
    for (std::size_t c = 0; c < checks_.size(); ++c) {
        if (first[c] == kAllFinite) continue;
        const Check& bad = checks_[c];
        const auto bits = firstBad_.downloadAs<std::uint32_t>((kSlots + c) * sizeof(std::uint32_t));
        const double value = static_cast<double>(std::bit_cast<float>(bits)) + bad.field->reference();
        throwNotFinite(bad.name, bad.sample, bad.field->size(), first[c], value, bad.when);
    }
}

}  // namespace eikon::sim::gpu
