#include "render/stages/GaussianKernel.h"

#include <algorithm>
#include <cmath>

namespace eikon::render {

std::vector<float> gaussianHalfKernel(double sigmaVoxels, int windowVoxels) {
    if (sigmaVoxels <= 0.0) return {1.0f};
    const int automatic = std::max(1, static_cast<int>(std::floor(3.0 * std::min(sigmaVoxels, 100.0))));
    const int radius = std::min(windowVoxels > 0 ? windowVoxels / 2 : automatic, kMaxSmoothingRadius);
    std::vector<double> weights(static_cast<std::size_t>(radius) + 1);
    double sum = 0.0;
    for (int offset = 0; offset <= radius; ++offset) {
        weights[static_cast<std::size_t>(offset)] = std::exp(-0.5 * offset * offset / (sigmaVoxels * sigmaVoxels));
        sum += (offset == 0 ? 1.0 : 2.0) * weights[static_cast<std::size_t>(offset)];
    }
    std::vector<float> half;
    for (double weight : weights) half.push_back(static_cast<float>(weight / sum));
    return half;
}

}  // namespace eikon::render
