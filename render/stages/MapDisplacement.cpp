#include "render/stages/MapDisplacement.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace eikon::render {

namespace {

// The displacement field on a lattice of nodes × nodes over the map.
class DisplacementField {
public:
    DisplacementField(int resolution, const std::vector<LandingPair>& pairs)
        : nodes_(std::clamp(static_cast<int>(std::lround(std::sqrt(pairs.size() / 4.0))), 1, resolution)),
          spacing_(static_cast<double>(resolution) / nodes_), values_(static_cast<std::size_t>(nodes_) * nodes_) {
        const double sigma = spacing_, reach = 3.0 * sigma;
        for (int j = 0; j < nodes_; ++j)
            for (int i = 0; i < nodes_; ++i) {
                const glm::dvec2 node = (glm::dvec2(i, j) + 0.5) * spacing_;
                glm::dvec2 sum(0.0);
                double weights = 0.0, nearest = 1e300;
                glm::dvec2 nearestDisplacement(0.0);
                for (const LandingPair& pair : pairs) {
                    const glm::dvec2 displacement = pair.reference - pair.scene;
                    const double distance = glm::length(pair.scene - node);
                    if (distance < nearest) nearest = distance, nearestDisplacement = displacement;
                    if (distance > reach) continue;
                    const double w = pair.power * std::exp(-0.5 * distance * distance / (sigma * sigma));
                    sum += w * displacement;
                    weights += w;
                }
                // A node no pair comes near takes its nearest pair's displacement.
                values_[static_cast<std::size_t>(j) * nodes_ + i] = weights > 0.0 ? sum / weights : nearestDisplacement;
            }
    }

    // Bilinear between node centres, held constant beyond the outer ones.
    glm::dvec2 at(glm::dvec2 texel) const {
        const double gx = std::clamp(texel.x / spacing_ - 0.5, 0.0, nodes_ - 1.0);
        const double gy = std::clamp(texel.y / spacing_ - 0.5, 0.0, nodes_ - 1.0);
        const int i = std::min(static_cast<int>(gx), nodes_ - 1), j = std::min(static_cast<int>(gy), nodes_ - 1);
        const int i1 = std::min(i + 1, nodes_ - 1), j1 = std::min(j + 1, nodes_ - 1);
        const double fx = gx - i, fy = gy - j;
        auto node = [&](int a, int b) { return values_[static_cast<std::size_t>(b) * nodes_ + a]; };
        return (1.0 - fy) * ((1.0 - fx) * node(i, j) + fx * node(i1, j)) + fy * ((1.0 - fx) * node(i, j1) + fx * node(i1, j1));
    }

private:
    int nodes_;
    double spacing_;
    std::vector<glm::dvec2> values_;
};

}  // namespace

MapChange displacedMapChange(const std::vector<float>& map, int resolution, const std::vector<LandingPair>& pairs) {
    if (pairs.empty() || resolution <= 0) return {};
    const DisplacementField field(resolution, pairs);
    std::vector<double> moved(map.size(), 0.0);
    for (int y = 0; y < resolution; ++y)
        for (int x = 0; x < resolution; ++x) {
            const std::size_t from = 3 * (static_cast<std::size_t>(y) * resolution + x);
            if (map[from] == 0.0f && map[from + 1] == 0.0f && map[from + 2] == 0.0f) continue;
            const glm::dvec2 centre(x + 0.5, y + 0.5);
            const glm::dvec2 to = centre + field.at(centre) - 0.5;  // in texel-centre units
            const glm::ivec2 base(static_cast<int>(std::floor(to.x)), static_cast<int>(std::floor(to.y)));
            const glm::dvec2 f = to - glm::dvec2(base);
            for (int k = 0; k < 4; ++k) {
                const glm::ivec2 t = base + glm::ivec2(k & 1, k >> 1);
                if (t.x < 0 || t.y < 0 || t.x >= resolution || t.y >= resolution) continue;
                const double share = ((k & 1) ? f.x : 1.0 - f.x) * ((k >> 1) ? f.y : 1.0 - f.y);
                const std::size_t into = 3 * (static_cast<std::size_t>(t.y) * resolution + t.x);
                for (std::size_t c = 0; c < 3; ++c) moved[into + c] += share * map[from + c];
            }
        }
    MapChange change;
    for (std::size_t i = 0; i < map.size(); ++i) {
        change.difference += std::abs(static_cast<double>(map[i]) - moved[i]);
        change.norm += std::abs(moved[i]);
    }
    return change;
}

}  // namespace eikon::render
