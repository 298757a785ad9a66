// shaders/common/lattice_directions.glsl compiled as C++: the lattices' links
// are distinct, come in opposite pairs, and their weights are a quadrature
// of the sphere — total 1, no mean direction, second moments δ/3 (the
// diffusion limit's), on 18 links the fourth moments too, and on 14 links
// the continuum's half-range flux.
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

}  // namespace
}  // namespace eikon
