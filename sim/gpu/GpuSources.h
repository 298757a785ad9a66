// The scene's sources on the GPU: the samples each source holds, listed once
// per field from the CPU's own SceneSources (sim/fluid/Sources.h), so both
// backends hold exactly the same samples at the same values, later regions
// overriding earlier ones as on the CPU. A hot plate's temperature is listed
// as T − T_amb, as the GPU stores it (GpuField.h).
#pragma once

#include "gl/GlObjects.h"
#include "sim/fluid/FluidState.h"
#include "sim/fluid/Sources.h"
#include "sim/gpu/GpuField.h"

#include <array>

namespace eikon::sim::gpu {

class GpuSources {
public:
    // `cells`: the solver's state, only for its lattices.
    GpuSources(const SceneSources& sources, const FluidState& cells, double ambientTemperature);

    // Hot plates: temperature; jets: concentration and dye.
    void applyScalars(GpuField& temperature, GpuField& concentration, GpuField& dye) const;
    // Jets: the velocity of every free face in their regions.
    void applyVelocity(std::array<GpuField, 3>& velocity) const;

private:
    struct HeldSamples {
        gl::Buffer entries;  // uvec2 (sample, float bits of the value)
        std::size_t count = 0;
    };
    void apply(const HeldSamples& held, GpuField& field) const;

    HeldSamples temperature_, concentration_, dye_;
    std::array<HeldSamples, 3> velocity_;
    gl::Program program_;
};

}  // namespace eikon::sim::gpu
