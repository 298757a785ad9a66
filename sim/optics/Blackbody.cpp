#include "sim/optics/Blackbody.h"

#include <glm/common.hpp>
#include <glm/exponential.hpp>

#include <algorithm>
#include <cmath>

namespace eikon::sim {

namespace {

constexpr double kPlanck = 6.62607015e-34;     // J·s
constexpr double kLightSpeed = 299792458.0;    // m/s
constexpr double kBoltzmann = 1.380649e-23;    // J/K
constexpr double kFirstWavelength = 360e-9;    // m: the CIE tables' range
constexpr double kLastWavelength = 830e-9;
constexpr int kWavelengthIntervals = 470;      // 1 nm

constexpr double kTableMinTemperature = 250.0;  // K
constexpr double kTableMaxTemperature = 50000.0;
constexpr int kTableIntervals = 4096;
constexpr double kTiny = 1e-300;  // ln(kTiny) stands for a channel of 0

// [Wyman13] eq. 2's piecewise Gaussian: width σ1 below the mean, σ2 above; λ in nm.
double lobe(double lambdaNm, double mean, double below, double above) {
    const double t = (lambdaNm - mean) / (lambdaNm < mean ? below : above);
    return std::exp(-0.5 * t * t);
}

}  // namespace

double planckSpectralRadiance(double wavelength, double temperature) {
    const double exponent = kPlanck * kLightSpeed / (wavelength * kBoltzmann * temperature);
    if (exponent > 700.0) return 0.0;  // e^−700: below any float radiance
    const double l5 = std::pow(wavelength, 5);
    return 2.0 * kPlanck * kLightSpeed * kLightSpeed / (l5 * std::expm1(exponent));
}

glm::dvec3 cieColourMatching(double wavelength) {
    const double nm = wavelength * 1e9;
    return {1.056 * lobe(nm, 599.8, 37.9, 31.0) + 0.362 * lobe(nm, 442.0, 16.0, 26.7) -
                0.065 * lobe(nm, 501.1, 20.4, 26.2),
            0.821 * lobe(nm, 568.8, 46.9, 40.5) + 0.286 * lobe(nm, 530.9, 16.3, 31.1),
            1.217 * lobe(nm, 437.0, 11.8, 36.0) + 0.681 * lobe(nm, 459.0, 26.0, 13.8)};
}

glm::dvec3 blackbodyXyz(double temperature) {
    const double step = (kLastWavelength - kFirstWavelength) / kWavelengthIntervals;
    glm::dvec3 sum(0.0);
    for (int i = 0; i <= kWavelengthIntervals; ++i) {
        const double lambda = kFirstWavelength + i * step;
        const double weight = (i == 0 || i == kWavelengthIntervals) ? 0.5 : 1.0;
        sum += weight * planckSpectralRadiance(lambda, temperature) * cieColourMatching(lambda);
    }
    return sum * step;
}

glm::dvec3 rec709FromXyz(const glm::dvec3& xyz) {
    // [IEC61966] §5.2 (sRGB: Rec. 709 primaries, D65 white).
    return {3.2406 * xyz.x - 1.5372 * xyz.y - 0.4986 * xyz.z,
            -0.9689 * xyz.x + 1.8758 * xyz.y + 0.0415 * xyz.z,
            0.0557 * xyz.x - 0.2040 * xyz.y + 1.0570 * xyz.z};
}

glm::dvec3 blackbodyRgb(double temperature) {
    return glm::max(rec709FromXyz(blackbodyXyz(temperature)), glm::dvec3(0.0));
}

BlackbodyTable::BlackbodyTable()
    : logMin_(std::log(kTableMinTemperature)),
      logStep_((std::log(kTableMaxTemperature) - std::log(kTableMinTemperature)) / kTableIntervals) {
    logRadiance_.reserve(kTableIntervals + 1);
    for (int i = 0; i <= kTableIntervals; ++i) {
        const glm::dvec3 rgb = blackbodyRgb(std::exp(logMin_ + i * logStep_));
        logRadiance_.push_back(glm::log(glm::max(rgb, glm::dvec3(kTiny))));
    }
}

glm::dvec3 BlackbodyTable::rgb(double temperature) const {
    if (!(temperature > 0.0)) return glm::dvec3(0.0);
    const double position = (std::log(temperature) - logMin_) / logStep_;
    const int i = std::clamp(static_cast<int>(std::floor(position)), 0, kTableIntervals - 1);
    const double t = position - i;
    const glm::dvec3 logValue = logRadiance_[i] + t * (logRadiance_[i + 1] - logRadiance_[i]);
    return glm::exp(glm::max(logValue, glm::dvec3(-700.0)));
}

}  // namespace eikon::sim
