// shaders/common/fresnel.glsl compiled as C++: the Fresnel equations' known
// values ([Born99] §1.5.2).
#include "shaders/common/cpp_shim.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <utility>

namespace eikon {
namespace {

using shader::diffuse_fresnel_reflectance;
using shader::fresnel_reflectance;

TEST(Fresnel, NormalIncidence) {
    EXPECT_NEAR(fresnel_reflectance(1.0f, 1.0f, 1.5f), 0.04f, 1e-6f);  // ((1 − 1.5)/(1 + 1.5))²
    EXPECT_NEAR(fresnel_reflectance(1.0f, 1.5f, 1.0f), 0.04f, 1e-6f);
    EXPECT_NEAR(fresnel_reflectance(1.0f, 1.33f, 1.33f), 0.0f, 1e-7f);
}

// At Brewster's angle tan θB = n_t/n_i the p wave is not reflected, so R is
// half of R_s = sin²(θi − θt)/sin²(θi + θt).
TEST(Fresnel, BrewsterAngleLeavesOnlyTheSWave) {
    const double brewster = std::atan(1.5);
    const double transmitted = std::asin(std::sin(brewster) / 1.5);
    const double rs = std::pow(std::sin(brewster - transmitted) / std::sin(brewster + transmitted), 2);
    EXPECT_NEAR(fresnel_reflectance(static_cast<float>(std::cos(brewster)), 1.0f, 1.5f), 0.5 * rs, 1e-6);
}

TEST(Fresnel, TotalInternalReflectionBeyondTheCriticalAngle) {
    const float critical = std::asin(1.0f / 1.5f);
    EXPECT_EQ(fresnel_reflectance(std::cos(critical + 0.01f), 1.5f, 1.0f), 1.0f);
    EXPECT_LT(fresnel_reflectance(std::cos(critical - 0.05f), 1.5f, 1.0f), 1.0f);
    EXPECT_NEAR(fresnel_reflectance(1e-4f, 1.0f, 1.5f), 1.0f, 1e-3f) << "grazing incidence reflects everything";
}

// R_d = 2∫R(μ)μ dμ by 200 000 midpoints in θ in double precision, with R in
// its angle form (R_s = sin²(θi − θt)/sin²(θi + θt), R_p = tan²(θi − θt)/tan²(θi + θt)),
// against the 16-point rule: within 1e-3 from either side of glass and
// water, and the two sides obey 1 − R_d(t → i) = (n_i/n_t)²(1 − R_d(i → t)).
double diffuseReflectanceByAngles(double ni, double nt) {
    const int n = 200000;
    const double half = std::numbers::pi / 2.0;
    double sum = 0.0;
    for (int k = 0; k < n; ++k) {
        const double incidence = (k + 0.5) * half / n;
        const double sinT = ni / nt * std::sin(incidence);
        double r = 1.0;
        if (sinT < 1.0) {
            const double transmitted = std::asin(sinT);
            const double rs = std::pow(std::sin(incidence - transmitted) / std::sin(incidence + transmitted), 2);
            const double rp = std::pow(std::tan(incidence - transmitted) / std::tan(incidence + transmitted), 2);
            r = 0.5 * (rs + rp);
        }
        sum += r * 2.0 * std::cos(incidence) * std::sin(incidence);  // 2μ dμ = 2 cos θ sin θ dθ
    }
    return sum * half / n;
}

TEST(Fresnel, DiffuseReflectanceIntegratesTheHemisphere) {
    for (const auto& [inside, outside] : {std::pair{1.5, 1.0}, std::pair{1.33, 1.0}, std::pair{1.5, 1.33}}) {
        const double leaving = diffuseReflectanceByAngles(inside, outside);
        const double entering = diffuseReflectanceByAngles(outside, inside);
        EXPECT_NEAR(diffuse_fresnel_reflectance(static_cast<float>(inside), static_cast<float>(outside)), leaving, 1e-3)
            << inside << " → " << outside;
        EXPECT_NEAR(diffuse_fresnel_reflectance(static_cast<float>(outside), static_cast<float>(inside)), entering, 1e-3)
            << outside << " → " << inside;
        EXPECT_NEAR(1.0 - entering, std::pow(inside / outside, 2) * (1.0 - leaving), 1e-4);
    }
    EXPECT_NEAR(diffuse_fresnel_reflectance(1.2f, 1.2f), 0.0f, 1e-7f);
}

}  // namespace
}  // namespace eikon
