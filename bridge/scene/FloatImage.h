// A linear RGBA float image in memory: an environment map as io/image reads
// it and the view stage uploads it.
#pragma once

#include <vector>

namespace eikon {

struct FloatImage {
    int width = 0, height = 0;
    std::vector<float> rgba;  // linear, row 0 at the top
};

}  // namespace eikon
