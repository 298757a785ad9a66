// The double-precision reference tracer against closed forms: straight lines,
// the Luneburg focus on the far surface, Maxwell fish-eye imaging, the n·cosθ
// invariant and catenary of a linear slab, the mirage turning height and the
// glass sphere's paraxial focus.
#include "verify/reference/AnalyticFields.h"
#include "verify/reference/ReferenceTracer.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace eikon::reference {
namespace {

TEST(ReferenceTracer, UniformFieldGivesStraightLines) {
    const UniformField field(1.33);
    const ReferenceTracer tracer(field);
    const glm::dvec3 d = glm::normalize(glm::dvec3(1.0, 2.0, -0.5));
    const ReferenceResult result = tracer.trace(tracer.start(glm::dvec3(0.1, 0.2, 0.3), d), 2.0);
    EXPECT_NEAR(glm::length(result.state.x - (glm::dvec3(0.1, 0.2, 0.3) + 2.0 * d)), 0.0, 1e-12);
    EXPECT_NEAR(result.arcLength, 2.0, 1e-12);
}

// A parallel beam along +z meets the lens at impact parameter b; every ray
// leaves through the focus (0, 0, R) on the far surface (to 1e-8 R).
TEST(ReferenceTracer, LuneburgLensFocusesOnTheFarSurface) {
    const double radius = 0.5;
    const LuneburgField field(glm::dvec3(0.0), radius);
    const ReferenceTracer tracer(field);
    for (double b : {0.05, 0.3, 0.6, 0.9, 0.99}) {
        const glm::dvec3 entry(b * radius, 0.0, -std::sqrt(1.0 - b * b) * radius - 1e-3);
        const ReferenceResult result =
            tracer.trace(tracer.start(entry, {0, 0, 1}), 4.0, [&](const RayState& s) { return s.x.z - radius; });
        ASSERT_TRUE(result.eventHit) << b;
        EXPECT_LT(std::hypot(result.state.x.x, result.state.x.y), 1e-8 * radius) << "impact " << b;
        EXPECT_LT(result.maxInvariantError, 1e-8);  // ∇n has a kink at r = R
    }
}

// Rays from P in several directions cross the plane through the image
// P' = −R²P/|P|² (normal to OP) at P' itself (to 1e-8 m).
TEST(ReferenceTracer, MaxwellFishEyeImagesPointToItsInversion) {
    const FishEyeField field(2.0, 1.0);
    const ReferenceTracer tracer(field);
    const glm::dvec3 p(0.8, 0.1, 0.0);
    const glm::dvec3 image = field.image(p);
    const glm::dvec3 axis = glm::normalize(image - p);
    for (double angle : {0.0, 0.2, 0.6, 1.0, 1.3}) {
        const glm::dvec3 side = glm::normalize(glm::cross(axis, glm::dvec3(0.3, 0.5, 1.0)));
        const glm::dvec3 direction = std::cos(angle) * axis + std::sin(angle) * side;
        const ReferenceResult result = tracer.trace(tracer.start(p, direction), 20.0, [&](const RayState& s) {
            return glm::dot(s.x - image, axis);
        });
        ASSERT_TRUE(result.eventHit) << angle;
        EXPECT_LT(glm::length(result.state.x - image), 1e-8) << "angle " << angle;
    }
}

// n = a + b·y: the horizontal part of v (n·cosθ) stays C, |v| stays n, and the
// path is the catenary n(y(x)) = C·cosh(b(x − x_v)/C) (to 1e-9 m).
TEST(ReferenceTracer, LinearSlabKeepsInvariantAndFollowsCatenary) {
    const double a = 1.0, b = 0.25;
    const LinearSlabField field(a, b);
    const ReferenceTracer tracer(field);
    const glm::dvec3 d = glm::normalize(glm::dvec3(1.0, -0.2, 0.0));
    const glm::dvec3 x0(0.0, 0.5, 0.0);
    const double n0 = a + b * x0.y, invariant = n0 * d.x;
    const double vertexX = x0.x + invariant / b * std::acosh(n0 / invariant);
    for (double length : {0.3, 0.8, 1.5}) {
        const ReferenceResult result = tracer.trace(tracer.start(x0, d), length);
        const RayState& s = result.state;
        EXPECT_NEAR(s.v.x, invariant, 1e-12);
        EXPECT_NEAR(glm::length(s.v), a + b * s.x.y, 1e-10);
        const double predictedY = (invariant * std::cosh(b * (s.x.x - vertexX) / invariant) - a) / b;
        EXPECT_NEAR(s.x.y, predictedY, 1e-9) << "after " << length << " m";
    }
}

// Mirage n = n∞ − δ·exp(−y/L): a ray heading down turns (v·ŷ = 0) at the
// height where n equals its invariant (to 1e-9 m).
TEST(ReferenceTracer, MirageRayTurnsWhereIndexEqualsInvariant) {
    const MirageField field(1.05, 0.05, 0.1);
    const ReferenceTracer tracer(field);
    for (double slope : {0.05, 0.1, 0.2}) {
        const glm::dvec3 d = glm::normalize(glm::dvec3(1.0, -slope, 0.0));
        const glm::dvec3 x0(0.0, 0.3, 0.0);
        const double invariant = field.index(x0) * d.x;
        const double expected = field.turningHeight(invariant);
        ASSERT_GT(expected, 0.0);
        const ReferenceResult result =
            tracer.trace(tracer.start(x0, d), 50.0, [](const RayState& s) { return s.v.y; });
        ASSERT_TRUE(result.eventHit);
        EXPECT_NEAR(result.state.x.y, expected, 1e-9) << "slope " << slope;
    }
}

// Glass sphere n = 1.5, R = 0.25 m, surface smoothed over w = 1e-4 R: a
// near-axis ray (b = 0.005 R) crosses the axis nR/(2(n − 1)) beyond the
// centre, to within the spherical aberration and smoothing (1e-4 relative).
TEST(ReferenceTracer, GlassSphereParaxialFocus) {
    const double radius = 0.25;
    const GlassSphereField field(glm::dvec3(0.0), radius, 1.5, 1e-4 * radius);
    const ReferenceTracer tracer(field, {.maxStep = 0.2e-4 * radius});  // steps cannot leap the surface
    const double b = 0.005 * radius;
    const ReferenceResult result = tracer.trace(tracer.start(glm::dvec3(b, 0.0, -2.0 * radius), {0, 0, 1}), 5.0,
                                                [](const RayState& s) { return s.x.x; });
    ASSERT_TRUE(result.eventHit);
    EXPECT_NEAR(result.state.x.z / field.paraxialFocusFromCentre(), 1.0, 1e-4);
}

}  // namespace
}  // namespace eikon::reference
