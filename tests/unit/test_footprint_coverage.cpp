// shaders/common/footprint_coverage.glsl compiled as C++: the texel coverage
// of a triangle against closed forms, and the partition of its area — the
// wavefront deposit conserves power only if the coverages of the texels a
// footprint touches sum to its area.
#include "shaders/common/cpp_shim.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace eikon {
namespace {

using shader::triangle_texel_coverage;
using shader::twice_signed_area;
using glm::vec2;

TEST(FootprintCoverage, ClosedForms) {
    // Inside the texel: the whole triangle.
    EXPECT_FLOAT_EQ(triangle_texel_coverage(vec2(0.1f, 0.1f), vec2(0.9f, 0.1f), vec2(0.1f, 0.9f), vec2(0.0f)), 0.32f);
    // Half the texel, its diagonal triangle, either orientation.
    EXPECT_FLOAT_EQ(triangle_texel_coverage(vec2(0.0f), vec2(1.0f, 0.0f), vec2(0.0f, 1.0f), vec2(0.0f)), 0.5f);
    EXPECT_FLOAT_EQ(triangle_texel_coverage(vec2(0.0f), vec2(0.0f, 1.0f), vec2(1.0f, 0.0f), vec2(0.0f)), 0.5f);
    // A triangle holding the whole texel covers exactly 1.
    EXPECT_FLOAT_EQ(triangle_texel_coverage(vec2(-5.0f), vec2(10.0f, -5.0f), vec2(-5.0f, 10.0f), vec2(0.0f)), 1.0f);
    // Disjoint: nothing.
    EXPECT_FLOAT_EQ(triangle_texel_coverage(vec2(2.0f), vec2(3.0f, 2.0f), vec2(2.0f, 3.0f), vec2(0.0f)), 0.0f);
    // The hypotenuse x + y = 3 cuts the corner x + y ≤ 3 off the square [1.25, 2.25]²: a right
    // triangle of legs 0.5.
    EXPECT_NEAR(triangle_texel_coverage(vec2(0.0f), vec2(3.0f, 0.0f), vec2(0.0f, 3.0f), vec2(1.25f, 1.25f)), 0.125f,
                1e-6f);
}

TEST(FootprintCoverage, TexelsPartitionTheTriangle) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> coordinate(-3.0f, 3.0f);
    for (int trial = 0; trial < 200; ++trial) {
        const vec2 a(coordinate(random), coordinate(random)), b(coordinate(random), coordinate(random)),
            c(coordinate(random), coordinate(random));
        double sum = 0.0;
        for (int j = -4; j < 4; ++j)
            for (int i = -4; i < 4; ++i) sum += triangle_texel_coverage(a, b, c, vec2(float(i), float(j)));
        const double area = 0.5 * std::abs(twice_signed_area(a, b, c));
        EXPECT_NEAR(sum, area, 2e-5 * std::max(1.0, area)) << "trial " << trial;
    }
}

// Small, thin triangles with nearly level edges, as refined patches are, in
// the coordinates the wavefront pass uses (from the footprint's first texel):
// the coverages of the texels they touch sum to their area to 5e-4 — float's
// resolution of slivers 1e-6 texels thick, or 1e-9 texel² — where subtracting antiderivatives
// inside the band lost a percent.
TEST(FootprintCoverage, SmallTrianglesAreConserved) {
    std::mt19937 random(11);
    std::uniform_real_distribution<float> position(0.0f, 2.0f), offset(-0.02f, 0.02f);
    for (int trial = 0; trial < 2000; ++trial) {
        const vec2 a(position(random), position(random));
        const vec2 b = a + vec2(10.0f * offset(random), 1e-4f * offset(random));
        const vec2 c = a + vec2(offset(random), offset(random));
        double sum = 0.0;
        for (int j = -1; j < 4; ++j)
            for (int i = -1; i < 4; ++i) sum += triangle_texel_coverage(a, b, c, vec2(float(i), float(j)));
        const double area = 0.5 * std::abs(twice_signed_area(a, b, c));
        EXPECT_NEAR(sum, area, 5e-4 * area + 1e-9) << "trial " << trial;
    }
}

}  // namespace
}  // namespace eikon
