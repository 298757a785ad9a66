#include "render/stages/RelativeChange.h"

#include <cmath>

namespace eikon::render {

double relativeL1OfRgb(const std::vector<float>& a, const std::vector<float>& b) {
    double difference = 0.0, norm = 0.0;
    for (std::size_t i = 0; i + 3 < b.size(); i += 4)
        for (std::size_t c = 0; c < 3; ++c) {
            difference += std::abs(static_cast<double>(a[i + c]) - b[i + c]);
            norm += std::abs(static_cast<double>(b[i + c]));
        }
    return norm > 0.0 ? difference / norm : 0.0;
}

double relativeL1OfVectors(const std::vector<float>& a, const std::vector<float>& b, std::size_t components) {
    double difference = 0.0, norm = 0.0;
    for (std::size_t i = 0; i + components <= b.size(); i += components) {
        double differenceSquared = 0.0, normSquared = 0.0;
        for (std::size_t c = 0; c < components; ++c) {
            const double d = static_cast<double>(a[i + c]) - b[i + c];
            differenceSquared += d * d;
            normSquared += static_cast<double>(b[i + c]) * b[i + c];
        }
        difference += std::sqrt(differenceSquared);
        norm += std::sqrt(normSquared);
    }
    return norm > 0.0 ? difference / norm : 0.0;
}

}  // namespace eikon::render
