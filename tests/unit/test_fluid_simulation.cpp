// FluidSimulation as the frame loop uses it: frames and substeps, NaN/Inf
// guards, field output on the render grid, solids and source regions.
#include "sim/fluid/FluidSimulation.h"

#include "sim/SceneFields.h"

#include "bridge/core/Error.h"
#include "sim/optics/OpticalMapping.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace eikon::sim {
namespace {

const GridSpec kRenderGrid{glm::ivec3(20, 24, 20), glm::dvec3(-0.25, 0.0, -0.25), glm::dvec3(0.25, 0.6, 0.25)};

SimDesc smallAir() {
    SimDesc desc;
    desc.resolution = glm::ivec3(12, 12, 12);
    desc.bounds = BoxShape{glm::dvec3(-0.2, 0.0, -0.2), glm::dvec3(0.2, 0.4, 0.2)};
    return desc;
}

// The solver's fields mapped onto the render grid with n_ref = 1, as
// sim::SceneFields does each frame.
void writeFields(const FluidSimulation& sim, const SimDesc& desc, FieldSet& fields) {
    fields.grid = kRenderGrid;
    fields.referenceIndex = 1.0;
    writeOpticalFields(OpticalModel(desc), sim.scalars(), fields);
}

std::string messageOf(FluidSimulation& sim) {
    try {
        sim.step(0.01);
    } catch (const NumericalBreakdown& error) {
        return error.what();
    }
    return "no error";
}

// NaN/Inf in the state is caught at the next check with the keys behind the
// phase, field and cell: at the start of the substep for values set from
// outside, after the phase that made them otherwise (a thermal_expansion of
// 1e300 overflows buoyancy: its keys are named).
TEST(FluidSimulation, NonFiniteValuesAreCaughtWithFieldAndCell) {
    {
        FluidSimulation sim(smallAir(), kRenderGrid);
        sim.state().temperature(3, 4, 5) = std::numeric_limits<double>::quiet_NaN();
        EXPECT_EQ(messageOf(sim),
                  "sim (the solver's temperature at cell (3, 4, 5) of sim.resolution, at the start of a substep): expected a "
                  "finite value, found nan");
    }
    {
        FluidSimulation sim(smallAir(), kRenderGrid);
        sim.state().flow.velocity[1](2, 7, 1) = std::numeric_limits<double>::infinity();
        EXPECT_EQ(messageOf(sim),
                  "sim (the solver's velocity_y at face (2, 7, 1) of sim.resolution, at the start of a substep): expected a "
                  "finite value, found inf");
    }
    {
        FluidSimulation sim(smallAir(), kRenderGrid);
        sim.state().dye(0, 11, 6) = -std::numeric_limits<double>::infinity();
        EXPECT_EQ(messageOf(sim), "sim (the solver's dye at cell (0, 11, 6) of sim.resolution, at the start of a substep): "
                                  "expected a finite value, found -inf");
    }
    {
        SimDesc desc = smallAir();
        desc.thermalExpansion = 1e300;  // buoyancy overflows at the one hot cell
        FluidSimulation sim(desc, kRenderGrid);
        sim.state().temperature(1, 2, 3) += 1e10;
        EXPECT_EQ(messageOf(sim), "sim.sources, sim.thermal_expansion, sim.concentration_expansion, sim.gravity, "
                                  "sim.vorticity_confinement (the solver's velocity_y at face (1, 2, 3) of "
                                  "sim.resolution, after sources): expected a finite value, found inf");
    }
}

// A frame advances frame_time in at least `substeps` substeps, more where
// the flow would exceed the CFL target.
TEST(FluidSimulation, FramesSplitIntoSubstepsByTheCflTarget) {
    SimDesc desc = smallAir();
    desc.frameTime = 0.1;
    desc.substeps = 2;
    desc.cfl = 1.0;
    desc.boundaries[0] = desc.boundaries[1] = SimDesc::Boundary::Open;  // a uniform x flow passes through
    FluidSimulation sim(desc, kRenderGrid);
    sim.advanceFrame();
    EXPECT_EQ(sim.lastSubsteps(), 2);
    EXPECT_DOUBLE_EQ(sim.time(), 0.1);
    // 1 m/s across 1/30 m cells: 0.1 s is 3 cells, so at CFL 1 at least 3 substeps.
    for (double& v : sim.state().flow.velocity[0].values) v = 1.0;
    sim.advanceFrame();
    EXPECT_GE(sim.lastSubsteps(), 3);
    EXPECT_NEAR(sim.time(), 0.2, 1e-15);
    const auto& timings = sim.lastTimings();
    ASSERT_EQ(timings.size(), 4u);
    EXPECT_EQ(timings[1].phase, "advection");
    EXPECT_EQ(timings[3].phase, "projection");
    EXPECT_GT(timings[1].milliseconds, 0.0);
    EXPECT_LE(timings[3].residual, desc.pressureTolerance);
}

// Fields land on the render grid (different box and resolution): uniform
// ambient air gives the Gladstone–Dale δn everywhere, also outside the solver box.
TEST(FluidSimulation, WritesGladstoneDaleIndexOnTheRenderGrid) {
    const SimDesc desc = smallAir();
    const FluidSimulation sim(desc, kRenderGrid);
    FieldSet fields;
    writeFields(sim, desc, fields);
    EXPECT_EQ(fields.grid.resolution, kRenderGrid.resolution);
    EXPECT_EQ(fields.referenceIndex, 1.0);
    const double expected = 2.93e-4 * 273.15 / 293.15;
    for (float delta : fields.deltaIndex) ASSERT_NEAR(delta, expected, 1e-9);
    EXPECT_FALSE(fields.hasExtinction());
    EXPECT_FALSE(fields.hasScattering());
    EXPECT_EQ(fields.indexVersion, 1u);
}

// A temperature linear in x is resampled exactly (trilinear) at render cells
// inside the solver box; versions move only for fields that changed.
TEST(FluidSimulation, ResamplesTrilinearlyAndBumpsOnlyChangedVersions) {
    SimDesc desc = smallAir();
    desc.dyeExtinction = Rgb(2.0, 1.0, 0.5);
    desc.dyeScattering = Rgb(1.0, 0.5, 0.25);
    FluidSimulation sim(desc, kRenderGrid);
    GridField& t = sim.state().temperature;
    for (int k = 0; k < 12; ++k)
        for (int j = 0; j < 12; ++j)
            for (int i = 0; i < 12; ++i) t(i, j, k) = 300.0 + 10.0 * sim.state().flow.position(t, i, j, k).x;
    FieldSet fields;
    writeFields(sim, desc, fields);
    EXPECT_EQ(fields.indexVersion, 1u);
    EXPECT_EQ(fields.extinctionVersion, 1u);  // zeros, but the model absorbs: present from the start
    const glm::dvec3 x = kRenderGrid.cellCentre(8, 5, 9);  // inside the central cells of the solver box
    const double n = 1.0 + 2.93e-4 * 273.15 / (300.0 + 10.0 * x.x);
    EXPECT_NEAR(fields.deltaIndex[kRenderGrid.linearIndex(8, 5, 9)], n - 1.0, 1e-10);

    writeFields(sim, desc, fields);  // nothing changed
    EXPECT_EQ(fields.indexVersion, 1u);
    EXPECT_EQ(fields.extinctionVersion, 1u);

    sim.state().dye(6, 6, 6) = 3.0;  // dye only: κ and σs change, the index does not
    writeFields(sim, desc, fields);
    EXPECT_EQ(fields.indexVersion, 1u);
    EXPECT_EQ(fields.extinctionVersion, 2u);
    EXPECT_EQ(fields.scatteringVersion, 2u);
    const glm::dvec3 c = sim.state().flow.position(sim.state().dye, 6, 6, 6);
    const glm::ivec3 cell = glm::ivec3((c - kRenderGrid.boundsMin) / kRenderGrid.voxelSize());
    EXPECT_GT(fields.extinction[3 * kRenderGrid.linearIndex(cell.x, cell.y, cell.z)], 0.0f);
}

TEST(FluidSimulation, SourceRegionWithoutCellsIsAnInputError) {
    SimDesc desc = smallAir();
    SimDesc::Source plate;
    plate.region = {glm::dvec3(0.0, 0.001, 0.0), glm::dvec3(0.01, 0.002, 0.01)};  // between cell centres
    desc.sources.push_back(plate);
    try {
        FluidSimulation sim(desc, kRenderGrid);
        FAIL() << "accepted an empty source region";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()),
                  "sim.sources[0]: expected a region holding at least one cell centre of the solver grid, found none");
    }
}

// Through SceneFields, as eikon run meets it, the message names the file.
TEST(FluidSimulation, SourceErrorsThroughTheSceneNameTheSceneFile) {
    Scene scene;
    scene.sourcePath = "plume.json";
    scene.grid.resolution = kRenderGrid.resolution;
    scene.grid.boundsMin = kRenderGrid.boundsMin;
    scene.grid.boundsMax = kRenderGrid.boundsMax;
    scene.sim = smallAir();
    SimDesc::Source plate;
    plate.region = {glm::dvec3(0.0, 0.001, 0.0), glm::dvec3(0.01, 0.002, 0.01)};
    scene.sim->sources.push_back(plate);
    try {
        SceneFields fields(scene);
        FAIL() << "accepted an empty source region";
    } catch (const InputError& error) {
        EXPECT_EQ(std::string(error.what()).rfind("plume.json: sim.sources[0]: expected a region", 0), 0u) << error.what();
    }
}

// A solid mask (as a voxelized mesh would give) blocks the flow: its faces
// stay at zero velocity, and a jet still drives the fluid around it.
TEST(FluidSimulation, SolidMaskAndJetShapeTheFlow) {
    SimDesc desc = smallAir();
    SimDesc::Source jet;
    jet.kind = SimDesc::Source::Kind::Jet;
    jet.region = {glm::dvec3(-0.05, 0.3, -0.05), glm::dvec3(0.05, 0.38, 0.05)};
    jet.velocity = glm::dvec3(0.0, -0.5, 0.0);
    jet.concentration = 1.0;
    jet.dye = 2.0;
    desc.sources.push_back(jet);
    FluidSimulation sim(desc, kRenderGrid);
    std::vector<std::uint8_t> solid(sim.domain().solid.size(), 0);
    for (int k = 4; k < 8; ++k)
        for (int i = 4; i < 8; ++i) solid[sim.domain().cellIndex(i, 3, k)] = 1;  // a slab below the jet
    sim.addSolidMask(solid);
    for (int s = 0; s < 10; ++s) sim.step(0.01);
    const MacGrid& mac = sim.state().flow;
    EXPECT_EQ(mac.velocity[1](5, 3, 5), 0.0);  // the slab's lower face
    EXPECT_EQ(mac.velocity[1](5, 4, 5), 0.0);  // and its upper face
    EXPECT_LT(mac.velocity[1](6, 7, 6), -0.1);  // the jet pushes down
    EXPECT_GT(sim.state().concentration(6, 8, 6), 0.5);
    EXPECT_GT(sim.state().dye(6, 8, 6), 1.0);
}

}  // namespace
}  // namespace eikon::sim
