#include "render/stages/LatticePhase.h"

#include "shaders/common/cpp_shim.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace eikon::render {

std::vector<float> latticeLinkSolidAngles(int directions, const glm::dvec3& voxelSize) {
    // Fibonacci points, equal areas on the sphere: 20 000 give each link's
    // share to about 1e-4.
    const int points = 20000;
    std::vector<double> count(static_cast<std::size_t>(directions), 0.0);
    for (int p = 0; p < points; ++p) {
        const double z = 1.0 - (2.0 * p + 1.0) / points;
        const double phi = p * 2.399963229728653;  // the golden angle
        const double s = std::sqrt(1.0 - z * z);
        const glm::vec3 direction(static_cast<float>(s * std::cos(phi)), static_cast<float>(s * std::sin(phi)),
                                  static_cast<float>(z));
        count[shader::lattice_nearest_slot(direction, glm::vec3(voxelSize), directions)] += 1.0;
    }
    std::vector<float> shares(count.size());
    for (std::size_t i = 0; i < count.size(); ++i) shares[i] = static_cast<float>(count[i] / points);
    return shares;
}

std::vector<float> latticePhaseTable(int directions, const glm::dvec3& voxelSize) {
    const std::vector<float> solidAngles = latticeLinkSolidAngles(directions, voxelSize);
    shader::LatticeLinkValues cells{};
    std::copy(solidAngles.begin(), solidAngles.end(), cells.value);
    const glm::vec3 voxel(voxelSize);
    const auto n = static_cast<std::size_t>(directions);
    std::vector<float> table(static_cast<std::size_t>(shader::LATTICE_PHASE_NODES) * n * n);
    for (int k = 0; k < shader::LATTICE_PHASE_NODES; ++k) {
        const float g = shader::lattice_phase_node_asymmetry(k);
        const double f = shader::lattice_delta_fraction(g);
        for (int j = 0; j < directions; ++j) {
            float* column = &table[(static_cast<std::size_t>(k) * n + static_cast<std::size_t>(j)) * n];
            if (g == 0.0f) {
                // Isotropic: the weights themselves, exactly.
                for (int i = 0; i < directions; ++i)
                    column[i] = shader::lattice_weight(shader::lattice_link(i, directions), directions);
                continue;
            }
            const shader::LatticeLinkValues shares = shader::lattice_hg_shares(
                shader::lattice_link_direction(j, voxel, directions), g, voxel, directions, cells,
                shader::LATTICE_PHASE_RINGS);
            double total = 0.0;
            std::vector<double> entries(n);
            for (int i = 0; i < directions; ++i) {
                entries[static_cast<std::size_t>(i)] = std::max(0.0, shares.value[i] - (i == j ? f : 0.0));
                total += entries[static_cast<std::size_t>(i)];
            }
            for (int i = 0; i < directions; ++i)
                column[i] = static_cast<float>(entries[static_cast<std::size_t>(i)] / total);
        }
    }
    return table;
}

}  // namespace eikon::render
