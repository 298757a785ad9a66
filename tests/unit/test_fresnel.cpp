// shaders/common/fresnel.glsl compiled as C++: the Fresnel equations' known
// values ([Born99] §1.5.2).
#include "shaders/common/cpp_shim.h"

#include <gtest/gtest.h>

#include <cmath>

namespace eikon {
namespace {

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

}  // namespace
}  // namespace eikon
