#include "sim/optics/LiquidOptics.h"

#include <algorithm>
#include <cmath>

namespace eikon::sim {

double lorentzLorenzRefraction(double index) {
    const double n2 = index * index;
    return (n2 - 1.0) / (n2 + 2.0);
}

double indexFromLorentzLorenz(double refraction) { return std::sqrt((1.0 + 2.0 * refraction) / (1.0 - refraction)); }

double mixedIndex(double indexA, double indexB, double concentration, SimDesc::Mixing rule) {
    const double c = std::clamp(concentration, 0.0, 1.0);
    if (rule == SimDesc::Mixing::Linear) return (1.0 - c) * indexA + c * indexB;
    return indexFromLorentzLorenz((1.0 - c) * lorentzLorenzRefraction(indexA) + c * lorentzLorenzRefraction(indexB));
}

}  // namespace eikon::sim
