// shaders/common/lattice_directions.glsl compiled as C++: the lattices' links
// are distinct, come in opposite pairs, and their weights are a quadrature
// of the sphere — total 1, no mean direction, second moments δ/3 (the
// diffusion limit's), on 18 links the fourth moments too, and on 14 links
// the continuum's half-range flux; and the quadrature that projects the
// Henyey–Greenstein distribution on the links (lattice_phase.glsl).
#include "shaders/common/cpp_shim.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <tuple>

namespace eikon {
namespace {

using shader::lattice_length_class;
using shader::lattice_link;
using shader::lattice_offset;
using shader::lattice_opposite;
using shader::lattice_weight;

// ⟨Π μ_axis^power⟩ over the lattice's unit link directions, by weight.
double moment(int directions, glm::ivec3 powers) {
    double sum = 0.0;
    for (int i = 0; i < directions; ++i) {
        const int d = lattice_link(i, directions);
        const glm::dvec3 u = glm::normalize(glm::dvec3(lattice_offset(d)));
        sum += lattice_weight(d, directions) * std::pow(u.x, powers.x) * std::pow(u.y, powers.y) * std::pow(u.z, powers.z);
    }
    return sum;
}

// Σ_{u_z > 0} w u_z: the share of an isotropic density's fluence φ that
// crosses a z face per unit time, in units of φ.
double halfRangeFlux(int directions) {
    double sum = 0.0;
    for (int i = 0; i < directions; ++i) {
        const int d = lattice_link(i, directions);
        const glm::dvec3 u = glm::normalize(glm::dvec3(lattice_offset(d)));
        if (u.z > 0.0) sum += lattice_weight(d, directions) * u.z;
    }
    return sum;
}

TEST(LatticeDirections, LinksAreDistinctNeighboursInOppositePairs) {
    for (int directions : {6, 14, 18}) {
        std::set<std::tuple<int, int, int>> seen;
        std::set<int> links;
        for (int i = 0; i < directions; ++i) links.insert(lattice_link(i, directions));
        for (int d : links) {
            const glm::ivec3 c = lattice_offset(d);
            const int length2 = c.x * c.x + c.y * c.y + c.z * c.z;
            const int lengthClass = lattice_length_class(d);
            EXPECT_EQ(length2, lengthClass < 3 ? 1 : (lengthClass < 6 ? 2 : 3)) << d;
            if (lengthClass < 3) {
                EXPECT_NE(c[lengthClass], 0) << d;
            } else if (lengthClass < 6) {
                EXPECT_EQ(c[(lengthClass - 1) % 3], 0) << d;
            }
            EXPECT_TRUE(seen.insert({c.x, c.y, c.z}).second) << d;
            const int j = lattice_opposite(d);
            EXPECT_TRUE(links.count(j)) << directions << " links lack the opposite of " << d;
            EXPECT_EQ(lattice_offset(j), -c) << d;
            EXPECT_EQ(lattice_opposite(j), d);
        }
        EXPECT_EQ(static_cast<int>(links.size()), directions);
    }
}

TEST(LatticeDirections, WeightsIntegrateTheSphere) {
    for (int directions : {6, 14, 18}) {
        EXPECT_NEAR(moment(directions, {0, 0, 0}), 1.0, 1e-7);
        for (int axis = 0; axis < 3; ++axis) {
            glm::ivec3 first(0), second(0);
            first[axis] = 1;
            second[axis] = 2;
            EXPECT_NEAR(moment(directions, first), 0.0, 1e-7);
            EXPECT_NEAR(moment(directions, second), 1.0 / 3.0, 1e-7) << directions << " links, axis " << axis;
        }
        EXPECT_NEAR(moment(directions, {1, 1, 0}), 0.0, 1e-7);
    }
    // The sphere's ⟨μ⁴⟩ = 1/5 and ⟨μx²μy²⟩ = 1/15: 18 links integrate them, 6 cannot (1/3 and 0).
    EXPECT_NEAR(moment(18, {4, 0, 0}), 1.0 / 5.0, 1e-7);
    EXPECT_NEAR(moment(18, {2, 2, 0}), 1.0 / 15.0, 1e-7);
    EXPECT_NEAR(moment(18, {0, 2, 2}), 1.0 / 15.0, 1e-7);
    EXPECT_NEAR(moment(6, {4, 0, 0}), 1.0 / 3.0, 1e-7);
}

// Marshak's condition: the continuum's half-range flux of an isotropic
// radiance is φ/4; 14 links meet it, 18 and 6 fall short.
TEST(LatticeDirections, FourteenLinksLeaveAFaceAtTheContinuumsRate) {
    EXPECT_NEAR(halfRangeFlux(14), 0.25, 1e-7);
    EXPECT_NEAR(halfRangeFlux(18), 1.0 / 30.0 + 4.0 / 15.0 / std::sqrt(2.0), 1e-7);
    EXPECT_NEAR(halfRangeFlux(6), 1.0 / 6.0, 1e-7);
}

TEST(LatticeDirections, MeanTransmittanceIsContinuousAtItsSeries) {
    for (float x : {0.0f, 1e-4f, 0.1f, 0.4999f, 0.5001f, 1.0f, 30.0f}) {
        const double exact = x > 0.0f ? -std::expm1(-static_cast<double>(x)) / x : 1.0;
        EXPECT_NEAR(shader::mean_transmittance(x), exact, 3e-7 * exact) << x;
    }
}

// The HG quantile inverts the distribution's closed-form CDF
// P(cos θ ≤ x) = (1 − g²)/(2g)·(1/√(1 + g² − 2gx) − 1/(1 + g)), and the
// birth quadrature (32 rings × 8 azimuths about the axis) integrates the
// first two moments of HG: ⟨cos θ⟩ = g and ⟨cos²θ⟩ = (1 + 2g²)/3 (the HG
// Legendre coefficients g^l), within 3e-3 at g = 0.8 and 0 about a skew axis
// (the midpoint rule's error in u at g = 0.8, h²/24 times the change of the
// integrand's slope over [0, 1]: 1.3e-3 and 2.4e-3 measured).
TEST(LatticeDirections, TheBirthQuadratureIntegratesHenyeyGreenstein) {
    for (double g : {0.8, 0.3, -0.5}) {
        for (double u : {0.01, 0.3, 0.5, 0.97}) {
            const double x = shader::lattice_hg_quantile(static_cast<float>(u), static_cast<float>(g));
            const double cdf = (1.0 - g * g) / (2.0 * g) * (1.0 / std::sqrt(1.0 + g * g - 2.0 * g * x) - 1.0 / (1.0 + g));
            EXPECT_NEAR(cdf, u, 2e-5) << g << " " << u;
        }
    }
    const glm::vec3 axis = glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f));
    for (double g : {0.8, 0.0}) {
        double first = 0.0, second = 0.0, unit = 0.0;
        const int n = shader::LATTICE_BIRTH_RINGS * shader::LATTICE_BIRTH_AZIMUTHS;
        for (int j = 0; j < shader::LATTICE_BIRTH_RINGS; ++j)
            for (int k = 0; k < shader::LATTICE_BIRTH_AZIMUTHS; ++k) {
                const glm::vec3 d =
                    shader::lattice_birth_direction(axis, static_cast<float>(g), j, k, shader::LATTICE_BIRTH_RINGS);
                const double mu = glm::dot(d, axis);
                first += mu / n;
                second += mu * mu / n;
                unit = std::max(unit, std::abs(static_cast<double>(glm::length(d)) - 1.0));
            }
        EXPECT_NEAR(first, g, 3e-3) << g;
        EXPECT_NEAR(second, (1.0 + 2.0 * g * g) / 3.0, 3e-3) << g;
        EXPECT_LT(unit, 1e-5);
    }
}

// The nearest link of a direction is the one at the smallest angle: along
// a link, that link; on cubic voxels the 6-link lattice's cells are the
// cube's faces (the largest component's axis).
TEST(LatticeDirections, TheNearestLinkIsTheClosestInAngle) {
    const glm::vec3 cube(1.0f);
    for (int directions : {6, 14, 18})
        for (int i = 0; i < directions; ++i) {
            const glm::vec3 along = glm::normalize(glm::vec3(lattice_offset(lattice_link(i, directions))));
            EXPECT_EQ(shader::lattice_nearest_slot(along, cube, directions), i) << directions;
        }
    EXPECT_EQ(shader::lattice_nearest_slot(glm::normalize(glm::vec3(0.2f, -0.9f, 0.5f)), cube, 6), 3);  // −y
    // 14 links: (0.6, 0.55, 0.58) lies nearer the body diagonal than any axis.
    EXPECT_EQ(lattice_link(shader::lattice_nearest_slot(glm::normalize(glm::vec3(0.6f, 0.55f, 0.58f)), cube, 14), 14), 18);
}

}  // namespace
}  // namespace eikon
