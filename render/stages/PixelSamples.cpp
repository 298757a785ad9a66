#include "render/stages/PixelSamples.h"

#include <cmath>

namespace eikon::render {

int sampleGridSide(int samples) {
    const int k = static_cast<int>(std::lround(std::sqrt(static_cast<double>(samples))));
    return samples >= 1 && k * k == samples ? k : 0;
}

glm::vec2 gridSampleOffset(int index, int k) {
    return {(static_cast<float>(index % k) + 0.5f) / static_cast<float>(k),
            (static_cast<float>(index / k) + 0.5f) / static_cast<float>(k)};
}

}  // namespace eikon::render
