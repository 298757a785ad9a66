// Mass correction of advected scalars on the GPU, as FluidSimulation's
// advectConserving and restoreTotal (sim/fluid/MassCorrection.h): before
// advection each field's total, smallest and largest value are recorded;
// after it the drift of the total that the MacCormack limiter causes
// ([Selle08] §3.1) is put back at the fronts, every value staying in
// [low, high] (a global mass-fixing step, cf. [Rasch90]; [Kim05] §4).
// Everything stays on the GPU: no value is read back (shaders/sim/mass_correction.comp).
#pragma once

#include "gl/GlObjects.h"
#include "sim/gpu/GpuField.h"

#include <array>
#include <cstddef>
#include <vector>

namespace eikon::sim::gpu {

class GpuMassCorrection {
public:
    // maxCount: the most fields one call handles.
    explicit GpuMassCorrection(std::size_t maxCount);

    // Before advection: each field's total, smallest and largest value, in
    // float64 on the GPU (budget f for fields[f]).
    void recordBudgets(const std::vector<GpuField*>& fields);
    // After advection: restoreTotal(field, total, low, high) of each field with
    // its recorded budget, as sim/fluid/MassCorrection.cpp. Reads nothing back.
    void restore(const std::vector<GpuField*>& fields);

private:
    enum Stage { Record, Measure, Restore };
    // Compiled on first use: [stage][pass] (Restore has one pass).
    const gl::Program& program(Stage stage, int pass);
    // Folds `field` into budget `budget` in two passes of `stage`.
    void reduce(Stage stage, const GpuField& field, std::size_t budget);

    static constexpr unsigned kGroups = 256;  // work groups of a reduction's first pass
    std::size_t maxCount_;
    gl::Buffer partials_;  // 3 float64 per work group
    gl::Buffer budgets_;   // per field: total, low, high, scale (float64)
    std::array<std::array<gl::Program, 2>, 3> programs_;
};

}  // namespace eikon::sim::gpu
