#include "render/stages/VolumeGlow.h"

#include <numbers>

namespace eikon::render {

GlowCells glowCells(const float* emission, const GridSpec& grid) {
    GlowCells glow;
    const std::size_t cells = grid.cellCount();
    std::vector<double> cumulative;
    double total = 0.0;
    for (std::size_t c = 0; c < cells; ++c) {
        const glm::dvec3 epsilon(emission[3 * c], emission[3 * c + 1], emission[3 * c + 2]);
        const double sum = epsilon.r + epsilon.g + epsilon.b;
        if (!(sum > 0.0)) continue;
        total += sum;
        cumulative.push_back(total);
        glow.power += epsilon;
        glow.cells.push_back({glm::vec4(glm::vec3(epsilon / sum), 0.0f), glm::uvec4(static_cast<unsigned>(c), 0u, 0u, 0u)});
    }
    for (std::size_t i = 0; i < glow.cells.size(); ++i)
        glow.cells[i].colour.w = static_cast<float>(cumulative[i] / total);
    if (!glow.cells.empty()) glow.cells.back().colour.w = 1.0f;  // no pick beyond the last cell
    glow.power *= 4.0 * std::numbers::pi * grid.voxelVolume();
    return glow;
}

void VolumeGlow::update(const float* emission, const GridSpec& grid) {
    const GlowCells glow = glowCells(emission, grid);
    power_ = glow.power;
    if (glow.cells.empty()) {
        cells_ = {};
        return;
    }
    cells_ = gl::Buffer(glow.cells.size() * sizeof(layout::GpuGlowCell), glow.cells.data());
}

void VolumeGlow::bind() const {
    if (cells_.id()) cells_.bindStorage(layout::kGlowCells);
}

}  // namespace eikon::render
