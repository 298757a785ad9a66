// Stability suite, CPU part: bad values in input grids are refused with
// their origin and position named before anything is traced, and the fluid solver stays
// bounded at CFL 20 with diffusion far beyond the explicit limit.
#include "bridge/core/Error.h"
#include "bridge/grid/FieldSet.h"
#include "tests/unit/FluidStiffRun.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <string_view>

namespace eikon {
namespace {

FieldSet smallFields() {
    FieldSet fields;
    fields.grid = GridSpec{glm::ivec3(4, 3, 2), glm::dvec3(0.0), glm::dvec3(1.0)};
    fields.referenceIndex = 1.0;
    fields.deltaIndex.assign(fields.grid.cellCount(), 0.1f);
    fields.extinction.assign(3 * fields.grid.cellCount(), 1.0f);
    fields.scattering.assign(3 * fields.grid.cellCount(), 0.5f);
    return fields;
}

// The message of the InputError validateFields throws, or "" when it passes.
std::string refusal(const FieldSet& fields) {
    try {
        validateFields(fields, [](std::string_view field, const glm::dvec3*) {
            return "frame 3: " + std::string(field);
        });
    } catch (const InputError& error) {
        return error.what();
    }
    return "";
}

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(StabilityInputs, FiniteFieldsPass) { EXPECT_EQ(refusal(smallFields()), ""); }

// NaN, ±Inf, and an index of zero or below: each refused, naming the field,
// the position of the cell (x, y, z) and the value found.
TEST(StabilityInputs, BadIndexValuesAreRefusedWithTheirCell) {
    const std::size_t cell = 1 + 4 * 2 + 12 * 1;  // (1, 2, 1)
    for (float bad : {kNaN, kInf, -kInf, -1.0f, -1.5f}) {
        FieldSet fields = smallFields();
        fields.deltaIndex[cell] = bad;
        const std::string message = refusal(fields);
        EXPECT_NE(message.find("frame 3: index (the refractive index at (0.375, 0.833333, 0.75) m)"), std::string::npos)
            << bad << ": " << message;
        EXPECT_NE(message.find("expected a finite index n > 0"), std::string::npos) << message;
    }
}

TEST(StabilityInputs, BadExtinctionAndScatteringAreRefusedWithTheirCell) {
    const std::size_t cell = 3 + 4 * 0 + 12 * 1;  // (3, 0, 1)
    for (float bad : {kNaN, kInf, -0.5f}) {
        FieldSet fields = smallFields();
        fields.extinction[3 * cell + 2] = bad;
        const std::string message = refusal(fields);
        EXPECT_NE(message.find("frame 3: extinction (the extinction κ at (0.875, 0.166667, 0.75) m)"), std::string::npos)
            << bad << ": " << message;
    }
    for (float bad : {kNaN, -0.5f, 2.0f}) {  // 2 > κ = 1
        FieldSet fields = smallFields();
        fields.scattering[3 * cell] = bad;
        const std::string message = refusal(fields);
        EXPECT_NE(message.find("frame 3: scattering (the scattering σs at (0.875, 0.166667, 0.75) m)"), std::string::npos)
            << bad << ": " << message;
    }
}

TEST(StabilityInputs, WrongSizedGridsAreRefused) {
    FieldSet fields = smallFields();
    fields.deltaIndex.pop_back();
    EXPECT_NE(refusal(fields).find("expected 24 values, found 23"), std::string::npos) << refusal(fields);
}

// The fluid solver at CFL 20 with every diffusivity 10⁴× the explicit limit
// (backward-Euler diffusion, MacCormack with a limiter): no NaN or Inf, the
// kinetic energy never exceeds its start (no forces; bound 1.001×), and the
// temperature stays within its initial range (the limiter's bound, 1e-6 K).
TEST(StabilityInputs, FluidSolverAtCfl20WithStiffDiffusion) {
    const sim::StiffRunResult run = sim::runStiffVortex(12, 20.0, 1e4, 10);
    EXPECT_TRUE(run.finite);
    EXPECT_LE(run.maxEnergyRatio, 1.001);
    EXPECT_GE(run.minTemperature, run.ambientTemperature - 1e-6);
    EXPECT_LE(run.maxTemperature, run.ambientTemperature + run.hotExcess + 1e-6);
}

}  // namespace
}  // namespace eikon
