// shaders/common/lattice_phase.glsl compiled as C++, and the phase table of
// render/stages/LatticePhase: how the multiple-scattering lattice shares
// Henyey–Greenstein light among its links. The shares about an axis keep
// HG's total, mean cosine and backward half-range flux (the latter checked
// against a numerical integral of HG written here), stay non-negative about
// any axis, and the later scatterings' phase matrix is non-negative with
// columns summing to 1 and the mean cosine of HG's remainder once the
// δ-Eddington forward peak f = g² is taken out (on 18 links at least that).
#include "render/stages/LatticePhase.h"
#include "shaders/common/cpp_shim.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace eikon {
namespace {

// HG in double ([Ihrke07] eq. 3), independent of phase.glsl.
double henyeyGreenstein(double mu, double g) {
    const double d = 1.0 + g * g - 2.0 * g * mu;
    return (1.0 - g * g) / (4.0 * M_PI * d * std::sqrt(d));
}

shader::LatticeLinkValues cellsOf(int directions, const glm::dvec3& voxel) {
    const std::vector<float> solidAngles = render::latticeLinkSolidAngles(directions, voxel);
    shader::LatticeLinkValues cells{};
    std::copy(solidAngles.begin(), solidAngles.end(), cells.value);
    return cells;
}

struct Moments {
    double total = 0.0, mean = 0.0, backward = 0.0, smallest = 1.0;
};

Moments momentsOf(const shader::LatticeLinkValues& shares, const glm::vec3& axis, const glm::vec3& voxel,
                  int directions) {
    Moments m;
    for (int i = 0; i < directions; ++i) {
        const double mu = glm::dot(glm::dvec3(shader::lattice_link_direction(i, voxel, directions)), glm::dvec3(axis));
        m.total += shares.value[i];
        m.mean += shares.value[i] * mu;
        m.backward += shares.value[i] * std::max(-mu, 0.0);
        m.smallest = std::min(m.smallest, static_cast<double>(shares.value[i]));
    }
    return m;
}

// (1 − g)/(1 + g + √(1 + g²))² against ∫ p(μ)·max(−μ, 0) dΩ by the midpoint
// rule on 200 000 intervals (error below 1e-9).
TEST(LatticePhase, TheBackwardFluxIsHenyeyGreensteinsIntegral) {
    for (double g : {-0.6, -0.2, 0.0, 1e-3, 0.3, 0.8, 0.95}) {
        const int n = 200000;
        double integral = 0.0;
        for (int k = 0; k < n; ++k) {
            const double t = (k + 0.5) / n;
            integral += 2.0 * M_PI * henyeyGreenstein(-t, g) * t / n;
        }
        EXPECT_NEAR(shader::lattice_hg_backward_flux(static_cast<float>(g)), integral, 1e-6) << g;
    }
    EXPECT_NEAR(shader::lattice_hg_backward_flux(0.8f), 0.021074, 1e-6);
    EXPECT_EQ(shader::lattice_hg_backward_flux(0.0f), 0.25f);
}

// About each link (the phase matrix's axes) on cubic voxels: the shares are
// non-negative, sum to 1, and have HG's mean cosine g and backward flux.
TEST(LatticePhase, SharesAboutALinkKeepHenyeyGreensteinsMoments) {
    const glm::dvec3 cube(1.0);
    for (int directions : {6, 14, 18}) {
        const shader::LatticeLinkValues cells = cellsOf(directions, cube);
        for (float g : {-0.5f, 0.2f, 0.5f, 0.8f, 0.9f})
            for (int j = 0; j < directions; ++j) {
                const glm::vec3 axis = shader::lattice_link_direction(j, glm::vec3(cube), directions);
                const Moments m = momentsOf(
                    shader::lattice_hg_shares(axis, g, glm::vec3(cube), directions, cells, shader::LATTICE_PHASE_RINGS),
                    axis, glm::vec3(cube), directions);
                EXPECT_GE(m.smallest, 0.0) << directions << " " << g << " " << j;
                EXPECT_NEAR(m.total, 1.0, 1e-5) << directions << " " << g << " " << j;
                EXPECT_NEAR(m.mean, g, 1e-4) << directions << " " << g << " " << j;
                EXPECT_NEAR(m.backward, shader::lattice_hg_backward_flux(g), 1e-4) << directions << " " << g << " " << j;
            }
    }
}

// The first scattering about a beam along +z on 14 links (32 rings): HG's
// backward flux, 0.0211 at g = 0.8, where the nearest-link projection alone
// kept 0.012.
TEST(LatticePhase, TheFirstScatteringKeepsTheBackwardFlux) {
    const glm::vec3 cube(1.0f), axis(0.0f, 0.0f, 1.0f);
    const Moments m = momentsOf(shader::lattice_hg_shares(axis, 0.8f, cube, 14, cellsOf(14, glm::dvec3(cube)),
                                                          shader::LATTICE_BIRTH_RINGS),
                                axis, cube, 14);
    EXPECT_NEAR(m.backward, 0.021074, 1e-4);
    EXPECT_NEAR(m.mean, 0.8, 1e-4);
    EXPECT_GE(m.smallest, 0.0);
}

// About any axis and on box voxels the shares stay non-negative and sum to
// 1 (where the full correction would go negative it is applied in part).
TEST(LatticePhase, SharesAreNonNegativeAboutAnyAxis) {
    unsigned state = 12345u;
    auto uniform = [&state] {
        state = state * 1664525u + 1013904223u;
        return (state >> 8) / 16777216.0f;
    };
    for (const glm::vec3 voxel : {glm::vec3(1.0f), glm::vec3(1.0f, 1.0f, 2.5f)})
        for (int directions : {6, 14, 18}) {
            const shader::LatticeLinkValues cells = cellsOf(directions, glm::dvec3(voxel));
            for (int trial = 0; trial < 200; ++trial) {
                const glm::vec3 axis =
                    glm::normalize(glm::vec3(uniform() - 0.5f, uniform() - 0.5f, uniform() - 0.5f) + 1e-3f);
                const float g = 1.9f * uniform() - 0.95f;
                const Moments m = momentsOf(
                    shader::lattice_hg_shares(axis, g, voxel, directions, cells, shader::LATTICE_BIRTH_RINGS), axis,
                    voxel, directions);
                EXPECT_GE(m.smallest, 0.0) << directions << " " << g;
                EXPECT_NEAR(m.total, 1.0, 1e-5) << directions << " " << g;
            }
        }
}

// The table: every column of every node non-negative and summing to 1; its
// mean cosine (g − f)/(1 − f) on 6 and 14 links, at least that on 18 (where
// the self link's share s is below f its diagonal is held at 0, which
// leaves (g − s)/(1 − s)); the g = 0
// node the weights themselves.
TEST(LatticePhase, TheTableIsTheRemaindersPhaseMatrix) {
    for (const glm::dvec3 voxel : {glm::dvec3(1.0), glm::dvec3(1.0, 1.0, 2.5)})
        for (int directions : {6, 14, 18}) {
            const std::vector<float> table = render::latticePhaseTable(directions, voxel);
            const auto n = static_cast<std::size_t>(directions);
            ASSERT_EQ(table.size(), static_cast<std::size_t>(shader::LATTICE_PHASE_NODES) * n * n);
            for (int k = 0; k < shader::LATTICE_PHASE_NODES; ++k) {
                const double g = shader::lattice_phase_node_asymmetry(k);
                const double f = shader::lattice_delta_fraction(static_cast<float>(g));
                for (int j = 0; j < directions; ++j) {
                    const glm::dvec3 cj(shader::lattice_link_direction(j, glm::vec3(voxel), directions));
                    double total = 0.0, mean = 0.0;
                    for (int i = 0; i < directions; ++i) {
                        const double p = table[(k * n + static_cast<std::size_t>(j)) * n + static_cast<std::size_t>(i)];
                        EXPECT_GE(p, 0.0);
                        total += p;
                        mean += p * glm::dot(glm::dvec3(shader::lattice_link_direction(i, glm::vec3(voxel), directions)), cj);
                        if (g == 0.0) {
                            EXPECT_EQ(p, shader::lattice_weight(shader::lattice_link(i, directions), directions));
                        }
                    }
                    EXPECT_NEAR(total, 1.0, 1e-5) << directions << " node " << k;
                    if (voxel == glm::dvec3(1.0) && std::abs(g) < 0.99) {
                        if (directions == 18) {
                            EXPECT_GE(mean, (g - f) / (1.0 - f) - 2e-4) << "node " << k;
                        } else {
                            EXPECT_NEAR(mean, (g - f) / (1.0 - f), 2e-4) << directions << " node " << k;
                        }
                    }
                }
            }
        }
}

// A cell's g between two nodes: the lower node and the upper's weight;
// g = 0 falls on a node exactly (so an isotropic cell reads the weights).
TEST(LatticePhase, ACellsAsymmetryFallsBetweenTwoNodes) {
    EXPECT_EQ(shader::lattice_phase_position(0.0f), glm::vec2(20.0f, 0.0f));
    EXPECT_EQ(shader::lattice_phase_position(-1.0f), glm::vec2(0.0f, 0.0f));
    EXPECT_EQ(shader::lattice_phase_position(1.0f), glm::vec2(39.0f, 1.0f));
    const glm::vec2 at = shader::lattice_phase_position(0.83f);
    EXPECT_EQ(at.x, 36.0f);
    EXPECT_NEAR(at.y, 0.6f, 1e-5);
}

}  // namespace
}  // namespace eikon
