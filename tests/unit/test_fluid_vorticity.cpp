// Vorticity confinement ([Fedkiw01] eqs. 9–11; sim/fluid/VorticityConfinement.h)
// against the closed form of a shear flow, and its effect on a plume.
#include "sim/fluid/VorticityConfinement.h"

#include "sim/fluid/FluidSimulation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace eikon::sim {
namespace {

// u_x = a·y² in a box y ∈ [0.1, 0.5] m: ω = (0, 0, −2a·y), |ω| = 2a·y,
// N = ŷ, N × ω = −2a·y x̂, so f = −ε·h·2a·y x̂ (eq. 11). The centred
// differences of y² and y are exact, so faces two cells inside the y walls
// (whose cells' neighbours are all interior) get exactly Δt·f; v and w stay 0.
TEST(VorticityConfinement, ShearFlowGetsTheClosedFormForce) {
    const glm::ivec3 cells(6, 16, 5);
    const GridSpec grid{cells, glm::dvec3(0.0, 0.1, 0.0), glm::dvec3(0.15, 0.5, 0.125)};  // h = 0.025 m
    FluidState state(grid, 293.15);
    const FluidDomain domain(cells, {});
    const double a = 3.0, epsilon = 0.7, dt = 0.01;
    GridField& u = state.flow.velocity[0];
    for (int k = 0; k < u.size.z; ++k)
        for (int j = 0; j < u.size.y; ++j)
            for (int i = 0; i < u.size.x; ++i) {
                const double y = state.flow.position(u, i, j, k).y;
                u(i, j, k) = a * y * y;
            }
    const GridField before = u;
    addVorticityConfinement(state, domain, epsilon, dt);
    const double h = 0.025;
    EXPECT_DOUBLE_EQ(confinementLength(state.flow.h), h);
    double largest = 0.0;
    for (int k = 0; k < cells.z; ++k)
        for (int j = 2; j < cells.y - 2; ++j)
            for (int i = 1; i < cells.x; ++i) {  // the interior x faces (the walls' are fixed)
                const double y = state.flow.position(u, i, j, k).y;
                const double expected = -dt * epsilon * h * 2.0 * a * y;
                EXPECT_NEAR(u(i, j, k) - before(i, j, k), expected, 1e-9 * std::abs(expected))
                    << "face (" << i << ", " << j << ", " << k << ")";
                largest = std::max(largest, std::abs(expected));
            }
    EXPECT_GT(largest, 1e-4);
    for (int axis = 1; axis < 3; ++axis)
        for (double value : state.flow.velocity[axis].values) EXPECT_EQ(value, 0.0) << "axis " << axis;
    for (int k = 0; k < cells.z; ++k)
        for (int j = 0; j < cells.y; ++j) {
            EXPECT_EQ(u(0, j, k), before(0, j, k)) << "closed wall";
            EXPECT_EQ(u(cells.x, j, k), before(cells.x, j, k)) << "closed wall";
        }
}

// A rigid rotation has the same vorticity everywhere: no gradient, no force.
TEST(VorticityConfinement, RigidRotationIsLeftAlone) {
    const glm::ivec3 cells(8, 8, 8);
    FluidState state(GridSpec{cells, glm::dvec3(-0.1), glm::dvec3(0.1)}, 293.15);
    for (int axis = 0; axis < 2; ++axis) {
        GridField& u = state.flow.velocity[axis];
        for (int k = 0; k < u.size.z; ++k)
            for (int j = 0; j < u.size.y; ++j)
                for (int i = 0; i < u.size.x; ++i) {
                    const glm::dvec3 p = state.flow.position(u, i, j, k);
                    u(i, j, k) = axis == 0 ? -2.0 * p.y : 2.0 * p.x;  // Ω = 2 rad/s about z
                }
    }
    const MacGrid before = state.flow;
    addVorticityConfinement(state, FluidDomain(cells, {}), 5.0, 0.1);
    for (int axis = 0; axis < 3; ++axis)
        for (std::size_t s = 0; s < before.velocity[axis].count(); ++s)
            EXPECT_NEAR(state.flow.velocity[axis].values[s], before.velocity[axis].values[s], 1e-12) << axis << " " << s;
}

// Over a hot plate the confinement spins up the eddies the plume already
// has, and the flow turns unsteady: over substeps 40–60 the velocity
// changes from one substep to the next by more, RMS over the faces, than
// without it.
TEST(VorticityConfinement, MakesThePlumeUnsteady) {
    SimDesc desc;
    desc.resolution = glm::ivec3(16, 24, 16);
    desc.bounds = BoxShape{glm::dvec3(-0.1, 0.0, -0.1), glm::dvec3(0.1, 0.3, 0.1)};
    desc.boundaries[faceIndex(1, 1)] = SimDesc::Boundary::Open;
    SimDesc::Source plate;
    plate.region = {glm::dvec3(-0.03, 0.0, -0.03), glm::dvec3(0.03, 0.0125, 0.03)};
    plate.temperature = 500.0;
    desc.sources.push_back(plate);
    const GridSpec render{glm::ivec3(8), desc.bounds->min, desc.bounds->max};
    // Σ over substeps 40–60 of Σ over faces of (u − u_before)².
    auto unsteadiness = [&](const SimDesc& run) {
        FluidSimulation sim(run, render);
        double sum = 0.0;
        for (int step = 0; step < 60; ++step) {
            const MacGrid before = static_cast<const FluidSimulation&>(sim).state().flow;
            sim.step(0.02);
            if (step < 40) continue;
            const MacGrid& after = static_cast<const FluidSimulation&>(sim).state().flow;
            for (int axis = 0; axis < 3; ++axis)
                for (std::size_t s = 0; s < after.velocity[axis].count(); ++s) {
                    const double d = after.velocity[axis].values[s] - before.velocity[axis].values[s];
                    sum += d * d;
                }
        }
        return std::sqrt(sum);
    };
    SimDesc confined = desc;
    confined.vorticityConfinement = 2.0;
    const double plain = unsteadiness(desc), spun = unsteadiness(confined);
    RecordProperty("unsteadiness_ratio", std::to_string(spun / plain));
    EXPECT_GT(spun, plain);
}

}  // namespace
}  // namespace eikon::sim
