#include "sim/voxelize/GaussianSmoothing.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace eikon::sim {

std::vector<double> gaussianKernel(double sigmaVoxels) {
    if (sigmaVoxels <= 0.0) return {1.0};
    const int radius = std::max(1, static_cast<int>(std::floor(3.0 * sigmaVoxels)));
    std::vector<double> kernel(static_cast<std::size_t>(2 * radius + 1));
    double sum = 0.0;
    for (int offset = -radius; offset <= radius; ++offset) {
        const double weight = std::exp(-0.5 * offset * offset / (sigmaVoxels * sigmaVoxels));
        kernel[static_cast<std::size_t>(offset + radius)] = weight;
        sum += weight;
    }
    for (double& weight : kernel) weight /= sum;
    return kernel;
}

void gaussianSmooth(std::vector<float>& values, const glm::ivec3& resolution, double sigmaVoxels) {
    const std::vector<double> kernel = gaussianKernel(sigmaVoxels);
    if (kernel.size() == 1) return;
    const int radius = static_cast<int>(kernel.size() / 2);
    const std::size_t strides[3] = {1, static_cast<std::size_t>(resolution.x),
                                    static_cast<std::size_t>(resolution.x) * static_cast<std::size_t>(resolution.y)};
    std::vector<float> source(values.size());
    for (int axis = 0; axis < 3; ++axis) {
        source = values;
        const int length = resolution[axis];
        const int other1 = resolution[(axis + 1) % 3];
        const int other2 = resolution[(axis + 2) % 3];
        const std::size_t stride = strides[axis];
        const std::size_t stride1 = strides[(axis + 1) % 3];
        const std::size_t stride2 = strides[(axis + 2) % 3];
        tbb::parallel_for(0, other2, [&](int b) {
            for (int a = 0; a < other1; ++a) {
                const std::size_t base = static_cast<std::size_t>(a) * stride1 + static_cast<std::size_t>(b) * stride2;
                for (int i = 0; i < length; ++i) {
                    double sum = 0.0;
                    for (int offset = -radius; offset <= radius; ++offset) {
                        const int clamped = std::clamp(i + offset, 0, length - 1);
                        sum += kernel[static_cast<std::size_t>(offset + radius)] *
                               source[base + static_cast<std::size_t>(clamped) * stride];
                    }
                    values[base + static_cast<std::size_t>(i) * stride] = static_cast<float>(sum);
                }
            }
        });
    }
}

}  // namespace eikon::sim
