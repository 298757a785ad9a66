#include "sim/fluid/SolverExport.h"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace eikon::sim {

ConstantSolverFields solverArraysNeverChange(const SimDesc& desc) {
    ConstantSolverFields constant{desc.sources.empty(), true, true, true};
    for (const SimDesc::Source& source : desc.sources) {
        if (source.kind == SimDesc::Source::Kind::HotPlate) {
            if (source.temperature != desc.ambientTemperature) constant.temperature = false;
        } else {
            if (source.concentration > 0.0) constant.concentration = false;
            if (source.dye > 0.0) constant.dye = false;
        }
    }
    return constant;
}

std::vector<NamedArray> solverArrays(const FluidState& state, const GridSpec& renderGrid, const SimDesc& desc,
                                     const std::vector<std::string>& names) {
    auto wants = [&](const char* name) {
        return names.empty() || std::find(names.begin(), names.end(), name) != names.end();
    };
    const bool withVelocity = wants("velocity"), withTemperature = wants("temperature"),
               withConcentration = wants("concentration"), withDye = wants("dye");
    const std::size_t cells = renderGrid.cellCount();
    const auto ambient = static_cast<float>(desc.ambientTemperature);
    NamedArray velocity{"velocity", 3, std::vector<float>(3 * cells, 0.0f), {"m/s", ArrayRole::Velocity}};
    NamedArray temperature{"temperature", 1, std::vector<float>(cells, ambient), {"K", ArrayRole::Scalar, ambient}};
    NamedArray concentration{"concentration", 1, std::vector<float>(cells, 0.0f), {"1", ArrayRole::Density}};
    NamedArray dye{"dye", 1, std::vector<float>(cells, 0.0f), {"1", ArrayRole::Density}};
    const MacGrid& flow = state.flow;
    const glm::ivec3 r = renderGrid.resolution;
    tbb::parallel_for(0, r.z, [&](int k) {
        for (int j = 0; j < r.y; ++j)
            for (int i = 0; i < r.x; ++i) {
                const glm::dvec3 x = renderGrid.cellCentre(i, j, k);
                if (!flow.grid.contains(x)) continue;
                const std::size_t cell = renderGrid.linearIndex(i, j, k);
                if (withVelocity) {
                    const glm::dvec3 u = flow.velocityAt(x);
                    for (int a = 0; a < 3; ++a) velocity.values[3 * cell + a] = static_cast<float>(u[a]);
                }
                if (withTemperature)
                    temperature.values[cell] =
                        static_cast<float>(sampleTrilinear(state.temperature, flow.lattice(state.temperature, x)));
                if (withConcentration)
                    concentration.values[cell] =
                        static_cast<float>(sampleTrilinear(state.concentration, flow.lattice(state.concentration, x)));
                if (withDye) dye.values[cell] = static_cast<float>(sampleTrilinear(state.dye, flow.lattice(state.dye, x)));
            }
    });
    const ConstantSolverFields constant = solverArraysNeverChange(desc);
    velocity.constant = constant.velocity;
    temperature.constant = constant.temperature;
    concentration.constant = constant.concentration;
    dye.constant = constant.dye;
    std::vector<NamedArray> arrays;
    for (NamedArray* array : {&velocity, &temperature, &concentration, &dye})
        if (wants(array->name.c_str())) arrays.push_back(std::move(*array));
    return arrays;
}

}  // namespace eikon::sim
