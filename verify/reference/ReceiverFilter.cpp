#include "verify/reference/ReceiverFilter.h"

#include <cstdlib>

namespace eikon::reference {

std::vector<double> binomialFilter(const std::vector<double>& map, int resolution) {
    std::vector<double> out(map.size());
    for (int j = 0; j < resolution; ++j)
        for (int i = 0; i < resolution; ++i) {
            double sum = 0.0, weights = 0.0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int x = i + dx, y = j + dy;
                    if (x < 0 || y < 0 || x >= resolution || y >= resolution) continue;
                    const double w = (2 - std::abs(dx)) * (2 - std::abs(dy));
                    sum += w * map[static_cast<std::size_t>(y * resolution + x)];
                    weights += w;
                }
            out[static_cast<std::size_t>(j * resolution + i)] = sum / weights;
        }
    return out;
}

}  // namespace eikon::reference
