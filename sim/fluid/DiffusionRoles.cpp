#include "sim/fluid/DiffusionRoles.h"

namespace eikon::sim {

DiffusionRoles diffusionRoles(const FluidDomain& domain, const SceneSources& sources, const MacGrid& mac) {
    DiffusionRoles roles;
    roles.scalars.assign(domain.solid.size(), DiffusionRole::Free);
    for (std::size_t c = 0; c < roles.scalars.size(); ++c)
        if (domain.solid[c]) roles.scalars[c] = DiffusionRole::Excluded;
    roles.temperature = roles.scalars;
    sources.holdTemperature(roles.temperature);
    for (int axis = 0; axis < 3; ++axis) {
        const GridField& u = mac.velocity[axis];
        std::vector<DiffusionRole>& faces = roles.velocity[static_cast<std::size_t>(axis)];
        faces.assign(u.count(), DiffusionRole::Free);
        for (int k = 0; k < u.size.z; ++k)
            for (int j = 0; j < u.size.y; ++j)
                for (int i = 0; i < u.size.x; ++i)
                    if (domain.faceIsFixed(axis, i, j, k)) faces[u.index(i, j, k)] = DiffusionRole::Fixed;
    }
    return roles;
}

}  // namespace eikon::sim
