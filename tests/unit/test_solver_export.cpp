// The solver's fields resampled onto the render grid for export.
#include "sim/SceneFields.h"
#include "sim/fluid/SolverExport.h"

#include <gtest/gtest.h>

namespace eikon::sim {
namespace {

// Linear fields are reproduced exactly by trilinear sampling: with
// T = 300 + 10·x + 5·z and u = (y, 0, 2) on an 8³ solver grid over [0, 1]³,
// render cells inside see the closed form, cells outside the ambient fluid at rest.
TEST(SolverExport, LinearFieldsResampleExactlyAndOutsideIsAmbient) {
    const GridSpec solver{{8, 8, 8}, {0, 0, 0}, {1, 1, 1}};
    FluidState state(solver, 290.0);
    const MacGrid& flow = state.flow;
    for (int k = 0; k < 8; ++k)
        for (int j = 0; j < 8; ++j)
            for (int i = 0; i < 8; ++i) {
                const glm::dvec3 x = flow.position(state.temperature, i, j, k);
                state.temperature(i, j, k) = 300.0 + 10.0 * x.x + 5.0 * x.z;
                state.concentration(i, j, k) = 0.25;
            }
    for (int k = 0; k < 8; ++k)
        for (int j = 0; j < 8; ++j)
            for (int i = 0; i < 9; ++i) state.flow.velocity[0](i, j, k) = flow.position(flow.velocity[0], i, j, k).y;
    for (int k = 0; k < 9; ++k)
        for (int j = 0; j < 8; ++j)
            for (int i = 0; i < 8; ++i) state.flow.velocity[2](i, j, k) = 2.0;

    // 5 cells over [0.1, 1.35]: centres 0.225 … 1.225, the last outside the solver box.
    const GridSpec render{{5, 5, 5}, {0.1, 0.1, 0.1}, {1.35, 1.35, 1.35}};
    SimDesc desc;
    desc.ambientTemperature = 290.0;
    const auto arrays = solverArrays(state, render, desc);
    ASSERT_EQ(arrays.size(), 4u);
    EXPECT_EQ(arrays[0].name, "velocity");
    EXPECT_EQ(arrays[1].name, "temperature");
    EXPECT_EQ(arrays[2].name, "concentration");
    EXPECT_EQ(arrays[3].name, "dye");
    for (int k = 0; k < 5; ++k)
        for (int j = 0; j < 5; ++j)
            for (int i = 0; i < 5; ++i) {
                const glm::dvec3 x = render.cellCentre(i, j, k);
                const std::size_t c = render.linearIndex(i, j, k);
                const bool inside = i < 4 && j < 4 && k < 4;
                // Inside the outer half cell sampling clamps, so only cells whose centre lies between sample rows are exact.
                const bool interior = x.x > 1.0 / 16 && x.x < 15.0 / 16 && x.y > 1.0 / 16 && x.y < 15.0 / 16 &&
                                      x.z > 1.0 / 16 && x.z < 15.0 / 16;
                if (!inside) {
                    EXPECT_EQ(arrays[1].values[c], 290.0f);
                    EXPECT_EQ(arrays[0].values[3 * c], 0.0f);
                    EXPECT_EQ(arrays[2].values[c], 0.0f);
                    continue;
                }
                EXPECT_NEAR(arrays[2].values[c], 0.25, 1e-6);
                EXPECT_NEAR(arrays[0].values[3 * c + 2], 2.0, 1e-6);
                if (!interior) continue;
                EXPECT_NEAR(arrays[1].values[c], 300.0 + 10.0 * x.x + 5.0 * x.z, 1e-4) << i << j << k;
                EXPECT_NEAR(arrays[0].values[3 * c + 0], x.y, 1e-6);
                EXPECT_NEAR(arrays[0].values[3 * c + 1], 0.0, 1e-6);
            }
}

// What the export writes once must really never change: a hot plate heats
// and moves a gas, while no source carries liquid B or dye, so over four
// frames concentration and dye keep every bit and are the arrays marked
// constant; temperature and velocity change and are not. A jet that carries
// dye makes dye change, and it is no longer marked.
TEST(SolverExport, ArraysMarkedConstantNeverChange) {
    Scene scene;
    scene.grid.resolution = glm::ivec3(12);
    scene.grid.boundsMin = glm::dvec3(0.0);
    scene.grid.boundsMax = glm::dvec3(0.3);
    SimDesc sim;
    sim.resolution = glm::ivec3(12);
    SimDesc::Source plate;
    plate.region = {glm::dvec3(0.1, 0.0, 0.1), glm::dvec3(0.2, 0.03, 0.2)};
    plate.temperature = 400.0;
    sim.sources.push_back(plate);
    scene.sim = sim;
    SceneFields fields(scene);
    const std::vector<NamedArray> first = fields.exportArrays();
    std::vector<std::string> marked;
    for (const NamedArray& array : first)
        if (array.constant) marked.push_back(array.name);
    EXPECT_EQ(marked, (std::vector<std::string>{"concentration", "dye"}));
    for (int frame = 0; frame < 3; ++frame) fields.advanceFrame();
    const std::vector<NamedArray> later = fields.exportArrays();
    ASSERT_EQ(later.size(), first.size());
    for (std::size_t a = 0; a < first.size(); ++a) {
        if (first[a].constant) EXPECT_EQ(later[a].values, first[a].values) << first[a].name;
        else EXPECT_NE(later[a].values, first[a].values) << first[a].name << " changes, and is not marked";
    }

    SimDesc::Source jet;
    jet.kind = SimDesc::Source::Kind::Jet;
    jet.dye = 0.5;
    sim.sources.push_back(jet);
    const ConstantSolverFields withDye = solverArraysNeverChange(sim);
    EXPECT_FALSE(withDye.dye);
    EXPECT_FALSE(withDye.concentration) << "a jet carries liquid B (concentration 1 by default)";
    EXPECT_FALSE(withDye.velocity);
}

}  // namespace
}  // namespace eikon::sim
