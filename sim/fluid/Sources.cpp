#include "sim/fluid/Sources.h"

#include "bridge/core/Error.h"
#include "sim/fluid/CellForceOnFaces.h"

#include <algorithm>

#include <glm/vector_relational.hpp>

namespace eikon::sim {

namespace {

bool inRegion(const BoxShape& box, const glm::dvec3& p) {
    return glm::all(glm::greaterThanEqual(p, box.min)) && glm::all(glm::lessThanEqual(p, box.max));
}

}  // namespace

void addBuoyancy(FluidState& state, const FluidDomain& domain, const SimDesc& desc, double dt) {
    const GridField& t = state.temperature;
    const GridField& c = state.concentration;
    auto acceleration = [&](int i, int j, int k) {  // (α c − β ΔT), times g below
        return desc.concentrationExpansion * c(i, j, k) -
               desc.thermalExpansion * (t(i, j, k) - desc.ambientTemperature);
    };
    for (int axis = 0; axis < 3; ++axis) {
        const double g = desc.gravity[axis];
        if (g == 0.0) continue;
        addCellForceOnFaces(state.flow.velocity[axis], domain, axis, dt * g, acceleration);
    }
}

SceneSources::SceneSources(const SimDesc& desc, const MacGrid& mac, const FluidDomain& domain) {
    const GridField cells = mac.cellField(0.0);
    for (std::size_t s = 0; s < desc.sources.size(); ++s) {
        const SimDesc::Source& source = desc.sources[s];
        Region region{source, {}, {}};
        for (int k = 0; k < cells.size.z; ++k)
            for (int j = 0; j < cells.size.y; ++j)
                for (int i = 0; i < cells.size.x; ++i)
                    if (inRegion(source.region, mac.position(cells, i, j, k))) region.cells.push_back(cells.index(i, j, k));
        if (region.cells.empty()) {
            throw InputError("sim.sources[" + std::to_string(s) + "]",
                             "a region holding at least one cell centre of the solver grid", "none");
        }
        if (source.kind == SimDesc::Source::Kind::Jet) {
            for (int axis = 0; axis < 3; ++axis) {
                const GridField& u = mac.velocity[axis];
                for (int k = 0; k < u.size.z; ++k)
                    for (int j = 0; j < u.size.y; ++j)
                        for (int i = 0; i < u.size.x; ++i)
                            if (!domain.faceIsFixed(axis, i, j, k) && inRegion(source.region, mac.position(u, i, j, k)))
                                region.faces[axis].push_back(u.index(i, j, k));
            }
        }
        regions_.push_back(std::move(region));
    }
}

std::array<double, 3> SceneSources::applyScalars(FluidState& state) const {
    std::array<double, 3> change{0.0, 0.0, 0.0};
    auto set = [&](GridField& field, std::size_t cell, double value, std::size_t scalar) {
        change[scalar] += value - field.values[cell];
        field.values[cell] = value;
    };
    for (const Region& region : regions_) {
        for (std::size_t cell : region.cells) {
            if (region.source.kind == SimDesc::Source::Kind::HotPlate) {
                set(state.temperature, cell, region.source.temperature, 0);
            } else {
                set(state.concentration, cell, region.source.concentration, 1);
                set(state.dye, cell, region.source.dye, 2);
            }
        }
    }
    return change;
}

bool SceneSources::holdsTemperature() const {
    return std::any_of(regions_.begin(), regions_.end(),
                       [](const Region& region) { return region.source.kind == SimDesc::Source::Kind::HotPlate; });
}

void SceneSources::applyVelocity(FluidState& state) const {
    for (const Region& region : regions_)
        for (int axis = 0; axis < 3; ++axis)
            for (std::size_t face : region.faces[axis]) state.flow.velocity[axis].values[face] = region.source.velocity[axis];
}

void SceneSources::holdTemperature(std::vector<DiffusionRole>& roles) const {
    for (const Region& region : regions_)
        if (region.source.kind == SimDesc::Source::Kind::HotPlate)
            for (std::size_t cell : region.cells) roles[cell] = DiffusionRole::Fixed;
}

}  // namespace eikon::sim
