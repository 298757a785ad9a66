#include "sim/gpu/GpuSources.h"

#include "bridge/layout/GpuLayouts.h"
#include "gl/ShaderLibrary.h"
#include "sim/gpu/GpuDispatch.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace eikon::sim::gpu {

namespace {

// Every sample `applied` holds a number in, where `marked` (all NaN) had none.
std::vector<std::uint32_t> heldEntries(const GridField& applied, double reference) {
    std::vector<std::uint32_t> entries;
    for (std::size_t s = 0; s < applied.count(); ++s) {
        if (std::isnan(applied.values[s])) continue;
        entries.push_back(static_cast<std::uint32_t>(s));
        entries.push_back(std::bit_cast<std::uint32_t>(static_cast<float>(applied.values[s] - reference)));
    }
    return entries;
}

}  // namespace

GpuSources::GpuSources(const SceneSources& sources, const FluidState& cells, double ambientTemperature)
    : program_(gl::compileComputeProgram("sim/apply_sources.comp")) {
    FluidState marked = cells;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (GridField* field : {&marked.temperature, &marked.concentration, &marked.dye, &marked.flow.velocity[0],
                             &marked.flow.velocity[1], &marked.flow.velocity[2]})
        std::fill(field->values.begin(), field->values.end(), nan);
    sources.applyScalars(marked);
    sources.applyVelocity(marked);
    auto list = [](const GridField& applied, double reference, const std::string& what) {
        const std::vector<std::uint32_t> entries = heldEntries(applied, reference);
        HeldSamples held;
        held.count = entries.size() / 2;
        if (held.count > 0)
            held.entries = gl::Buffer(entries.size() * sizeof(std::uint32_t), entries.data(), GL_DYNAMIC_STORAGE_BIT,
                                      gl::GpuResource{"sim.sources", "the samples the sources hold: " + what});
        return held;
    };
    temperature_ = list(marked.temperature, ambientTemperature, "temperature");
    concentration_ = list(marked.concentration, 0.0, "concentration");
    dye_ = list(marked.dye, 0.0, "dye");
    const char* const axes[3] = {"velocity x", "velocity y", "velocity z"};
    for (int axis = 0; axis < 3; ++axis) velocity_[axis] = list(marked.flow.velocity[axis], 0.0, axes[axis]);
}

void GpuSources::apply(const HeldSamples& held, GpuField& field) const {
    if (held.count == 0) return;
    program_.use();
    held.entries.bindStorage(layout::kSolverSourceCells);
    field.bind(layout::kSolverField);
    glUniform1ui(program_.uniform("count"), static_cast<GLuint>(held.count));
    dispatchOverEntries(program_, held.count);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void GpuSources::applyScalars(GpuField& temperature, GpuField& concentration, GpuField& dye) const {
    apply(temperature_, temperature);
    apply(concentration_, concentration);
    apply(dye_, dye);
}

void GpuSources::applyVelocity(std::array<GpuField, 3>& velocity) const {
    for (int axis = 0; axis < 3; ++axis) apply(velocity_[axis], velocity[axis]);
}

}  // namespace eikon::sim::gpu
