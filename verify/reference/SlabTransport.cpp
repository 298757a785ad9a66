#include "verify/reference/SlabTransport.h"

#include "bridge/core/Error.h"

#include <cmath>
#include <numbers>
#include <random>

namespace eikon::reference {

namespace {

// cos θ of a Henyey–Greenstein deflection for a uniform u (g = 0: isotropic).
double sampleCosine(double g, double u) {
    if (std::abs(g) < 1e-6) return 2.0 * u - 1.0;
    const double s = (1.0 - g * g) / (1.0 - g + 2.0 * g * u);
    return (1.0 + g * g - s * s) / (2.0 * g);
}

double binomialError(double fraction, long long n) { return std::sqrt(fraction * (1.0 - fraction) / static_cast<double>(n)); }

}  // namespace

double fresnelReflectance(double cosIncidence, double nFrom, double nTo) {
    const double cosI = std::min(1.0, std::abs(cosIncidence));
    const double sinT = nFrom / nTo * std::sqrt(std::max(0.0, 1.0 - cosI * cosI));
    if (sinT >= 1.0) return 1.0;
    const double cosT = std::sqrt(1.0 - sinT * sinT);
    const double s = (nFrom * cosI - nTo * cosT) / (nFrom * cosI + nTo * cosT);
    const double p = (nFrom * cosT - nTo * cosI) / (nFrom * cosT + nTo * cosI);
    return 0.5 * (s * s + p * p);
}

SlabFractions traceSlab(const SlabSetup& setup) {
    EIKON_CHECK_MSG(setup.opticalThickness > 0.0 && setup.albedo >= 0.0 && setup.albedo <= 1.0 &&
                        std::abs(setup.anisotropy) < 1.0 && setup.relativeIndex > 0.0 && setup.photons > 0,
                    "a slab of τ > 0, albedo in [0, 1], |g| < 1, index > 0 and some photons");
    const bool fresnel = setup.relativeIndex != 1.0;
    const double tau = setup.opticalThickness;
    std::mt19937_64 random(setup.seed * 0x9E3779B97F4A7C15ull + 1);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    long long reflected = 0, diffuse = 0, direct = 0, directBack = 0, absorbed = 0, collisions = 0;
    for (long long p = 0; p < setup.photons; ++p) {
        // Depth in optical units and direction cosine to the slab's normal;
        // in a plane-parallel slab only μ = cos θ matters, the azimuth
        // enters only through the change of μ at a scattering.
        double depth = 0.0, mu = 1.0;
        bool scattered = false;
        for (;;) {
            depth += mu * -std::log(1.0 - uniform(random));
            // A face met: left through, or mirrored back into the slab (the
            // rest of the free path folded back), perhaps more than once.
            bool left = false;
            while (!left && (depth < 0.0 || depth > tau)) {
                if (fresnel && uniform(random) < fresnelReflectance(mu, setup.relativeIndex, 1.0)) {
                    depth = depth < 0.0 ? -depth : 2.0 * tau - depth;
                    mu = -mu;
                    continue;
                }
                left = true;
            }
            if (left) {
                if (depth < 0.0)
                    ++(scattered ? reflected : directBack);
                else
                    ++(scattered ? diffuse : direct);
                break;
            }
            ++collisions;
            if (uniform(random) >= setup.albedo) {
                ++absorbed;
                break;
            }
            scattered = true;
            const double cosTheta = sampleCosine(setup.anisotropy, uniform(random));
            const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
            const double phi = 2.0 * std::numbers::pi * uniform(random);
            const double sinMu = std::sqrt(std::max(0.0, 1.0 - mu * mu));
            mu = mu * cosTheta + sinMu * sinTheta * std::cos(phi);  // spherical law of cosines
        }
    }
    const double n = static_cast<double>(setup.photons);
    SlabFractions result;
    result.reflected = static_cast<double>(reflected) / n;
    result.diffuselyTransmitted = static_cast<double>(diffuse) / n;
    result.directlyTransmitted = static_cast<double>(direct) / n;
    result.directlyReflected = static_cast<double>(directBack) / n;
    result.absorbed = static_cast<double>(absorbed) / n;
    result.reflectedError = binomialError(result.reflected, setup.photons);
    result.diffuselyTransmittedError = binomialError(result.diffuselyTransmitted, setup.photons);
    result.meanCollisions = static_cast<double>(collisions) / n;
    return result;
}

}  // namespace eikon::reference
