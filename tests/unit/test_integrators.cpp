// The integrators of shaders/common/integrators.glsl, compiled as C++ over
// GLM (the very code the photon shader runs), on closed-form index fields.
#include "shaders/common/cpp_shim.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace eikon::shader {
namespace {

// The field the integrators sample: set per test.
std::function<vec4(vec3)> currentField;
vec4 field_at(vec3 x) { return currentField(x); }

#include "shaders/common/integrators.glsl"

}  // namespace
}  // namespace eikon::shader

namespace eikon {
namespace {

using shader::vec3;
using shader::vec4;

enum class Scheme { Euler, Leapfrog, Rk4 };

void step(Scheme scheme, vec3& x, vec3& lost, vec3& v, vec4& field, float ds) {
    switch (scheme) {
        case Scheme::Euler: shader::integrate_euler(x, lost, v, field, ds); break;
        case Scheme::Leapfrog: shader::integrate_leapfrog(x, lost, v, field, ds); break;
        case Scheme::Rk4: shader::integrate_rk4(x, lost, v, field, ds); break;
    }
}

vec4 fishEye(vec3 p) {
    const float r2 = glm::dot(p, p);
    return vec4(-4.0f * p / ((1.0f + r2) * (1.0f + r2)), 2.0f / (1.0f + r2));
}

// Maxwell's fish-eye n = 2/(1 + r²): the ray through (0.5, 0) heading along
// +y is the circle of centre (−0.75, 0) and radius 1.25 (it cuts the unit
// circle at antipodal points). Returns | |x − c| − ρ | after arc length 2.
double circleError(Scheme scheme, float ds) {
    shader::currentField = fishEye;
    vec3 x(0.5f, 0.0f, 0.0f), lost(0.0f);
    vec4 field = shader::field_at(x);
    vec3 v(0.0f, field.w, 0.0f);
    for (int i = 0; i < static_cast<int>(std::lround(2.0 / ds)); ++i) step(scheme, x, lost, v, field, ds);
    return std::abs(glm::length(glm::dvec3(x) - glm::dvec3(-0.75, 0.0, 0.0)) - 1.25);
}

TEST(Integrators, ConvergeAtTheirOrder) {
    const double euler = circleError(Scheme::Euler, 0.02f) / circleError(Scheme::Euler, 0.01f);
    const double leapfrog = circleError(Scheme::Leapfrog, 0.02f) / circleError(Scheme::Leapfrog, 0.01f);
    std::printf("[ figure   ] fish-eye circle, error ratio for a halved step: euler %.2f, leapfrog %.2f; "
                "errors at ds = 0.02: euler %.2e, leapfrog %.2e, rk4 %.2e\n",
                euler, leapfrog, circleError(Scheme::Euler, 0.02f), circleError(Scheme::Leapfrog, 0.02f),
                circleError(Scheme::Rk4, 0.02f));
    EXPECT_NEAR(euler, 2.0, 0.3) << "first order";
    EXPECT_NEAR(leapfrog, 4.0, 0.6) << "second order";
    EXPECT_LT(circleError(Scheme::Rk4, 0.02f), 0.05 * circleError(Scheme::Leapfrog, 0.02f)) << "fourth order";
}

// Over twenty turns of that circle the symplectic leapfrog keeps |v| = n to
// 1e-3, while Euler's error grows without bound.
TEST(Integrators, LeapfrogKeepsTheInvariantOverManyOrbits) {
    shader::currentField = fishEye;
    double worst[2] = {0.0, 0.0};
    for (Scheme scheme : {Scheme::Euler, Scheme::Leapfrog}) {
        vec3 x(0.5f, 0.0f, 0.0f), lost(0.0f);
        vec4 field = shader::field_at(x);
        vec3 v = vec3(0.0f, field.w, 0.0f);
        // One turn of the circle above is about 6.3 in arc length; twenty turns at ds = 0.01.
        for (int i = 0; i < 20 * 629; ++i) {
            step(scheme, x, lost, v, field, 0.01f);
            worst[scheme == Scheme::Leapfrog] =
                std::max(worst[scheme == Scheme::Leapfrog], double{shader::eikonal_invariant_error(v, field.w)});
        }
    }
    std::printf("[ figure   ] fish-eye 20 turns, max invariant error: euler %.2e, leapfrog %.2e\n", worst[0], worst[1]);
    EXPECT_LT(worst[1], 1e-3);
    EXPECT_GT(worst[0], 10.0 * worst[1]);
}

TEST(Integrators, RenormalisationRestoresTheInvariant) {
    const vec3 v = shader::renormalised_direction(vec3(3.0f, 4.0f, 0.0f), 1.5f);
    EXPECT_NEAR(glm::length(v), 1.5f, 1e-6f);
    EXPECT_NEAR(v.x / v.y, 0.75f, 1e-6f);
}

}  // namespace
}  // namespace eikon
