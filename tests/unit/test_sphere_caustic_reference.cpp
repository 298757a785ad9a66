// The two ground truths of the showcase against each other and against the
// inverse-square law: integrateSphereCaustic (noise-free, one meridian plane)
// must equal the closed form where the sphere is invisible, and agree with the
// Monte Carlo traceSphereCaustic within its noise where it is not; and the
// beam's (integrateSphereCausticUnderBeam) keeps its irradiance and power.
#include "verify/reference/SphereCaustic.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <numeric>

namespace eikon::reference {
namespace {

// The texel average of the unobstructed irradiance I·h/(h² + r²)^{3/2}, by a
// 16×16 midpoint rule inside the texel (smooth: error ≪ 1e-5).
double inverseSquareTexel(const SphereCausticSetup& s, int i, int j) {
    const double texel = s.size / s.resolution, h = s.light.y - s.receiverCentre.y;
    double sum = 0.0;
    for (int b = 0; b < 16; ++b)
        for (int a = 0; a < 16; ++a) {
            const double x = -0.5 * s.size + (i + (a + 0.5) / 16.0) * texel;
            const double z = -0.5 * s.size + (j + (b + 0.5) / 16.0) * texel;
            sum += s.power / (4.0 * std::numbers::pi) * h / std::pow(h * h + x * x + z * z, 1.5);
        }
    return sum / 256.0;
}

TEST(SphereCausticReference, InvisibleSphereGivesTheInverseSquareLaw) {
    SphereCausticSetup setup;
    setup.sphereIndex = setup.mediumIndex;  // no refraction, no reflection
    setup.resolution = 64;
    const IrradianceMap map = integrateSphereCaustic(setup, 100'000);
    double worst = 0.0;
    for (int j = 0; j < setup.resolution; ++j)
        for (int i = 0; i < setup.resolution; ++i)
            worst = std::max(worst, std::abs(map.at(i, j) / inverseSquareTexel(setup, i, j) - 1.0));
    EXPECT_LE(worst, 1e-4);
}

TEST(SphereCausticReference, AgreesWithTheMonteCarloReference) {
    SphereCausticSetup setup;
    setup.resolution = 48;
    setup.rays = 4'000'000;
    const IrradianceMap exact = integrateSphereCaustic(setup, 100'000);
    const IrradianceMap sampled = traceSphereCaustic(setup);
    double difference = 0.0, total = 0.0, sampledTotal = 0.0;
    for (std::size_t t = 0; t < exact.irradiance.size(); ++t) {
        difference += std::abs(sampled.irradiance[t] - exact.irradiance[t]);
        total += exact.irradiance[t];
        sampledTotal += sampled.irradiance[t];
    }
    // Over 2304 texels, ~1700 rays each: Monte Carlo noise of ~2.4% per texel,
    // so ~2% in L1; the totals agree to the noise of all 4e6 rays.
    EXPECT_LE(difference / total, 0.03);
    EXPECT_NEAR(sampledTotal / total, 1.0, 2e-3);
}

// Under a parallel beam: where the sphere is invisible every texel gets the
// beam's irradiance; through the glass the map is the point light's (checked
// above) in the limit of a light far away, here 300 m up with the power that
// gives the beam's irradiance at the sphere. The far light's rays diverge by
// up to 1.4 mrad, so the maps differ as 1/height: 1.4% at 100 m, 0.51% at 300 m.
TEST(SphereCausticReference, BeamIsTheLimitOfAFarPointLight) {
    SphereCausticSetup setup;
    setup.centre = glm::dvec3(0.0);
    setup.receiverCentre = glm::dvec3(0.0, -0.4, 0.0);
    setup.size = 0.6;  // wider than the sphere: the far light's cone holds all of it
    setup.resolution = 32;
    constexpr double kIrradiance = 2.0, kHeight = 300.0;
    setup.sphereIndex = setup.mediumIndex;
    const IrradianceMap clear = integrateSphereCausticUnderBeam(setup, kIrradiance, 20'000);
    double worst = 0.0;
    for (double e : clear.irradiance) worst = std::max(worst, std::abs(e / kIrradiance - 1.0));
    EXPECT_LE(worst, 1e-4);

    setup.sphereIndex = 1.5;
    const IrradianceMap beam = integrateSphereCausticUnderBeam(setup, kIrradiance, 20'000);
    setup.light = glm::dvec3(0.0, kHeight, 0.0);
    setup.power = 4.0 * std::numbers::pi * kIrradiance * kHeight * kHeight;
    const IrradianceMap far = integrateSphereCaustic(setup, 20'000);
    double difference = 0.0, total = 0.0;
    for (std::size_t t = 0; t < beam.irradiance.size(); ++t) {
        difference += std::abs(far.irradiance[t] - beam.irradiance[t]);
        total += beam.irradiance[t];
    }
    EXPECT_LE(difference / total, 0.01);
    EXPECT_GT(beam.at(16, 16), 10.0 * kIrradiance);  // the sphere concentrates the beam on its axis
}

TEST(SphereCausticReference, RefusesAnOffAxisSetup) {
    SphereCausticSetup setup;
    setup.light.x = 0.1;
    EXPECT_THROW(integrateSphereCaustic(setup, 10), std::invalid_argument);
}

}  // namespace
}  // namespace eikon::reference
