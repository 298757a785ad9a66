// The part each sample plays in the implicit diffusion of each field
// (Diffusion.h): solid cells are Excluded from the scalars, hot-plate cells
// hold their temperature (Fixed), and faces on walls or solids keep their
// zero velocity (Fixed). One function, so both backends diffuse the same
// problem.
#pragma once

#include "sim/fluid/Boundaries.h"
#include "sim/fluid/Diffusion.h"
#include "sim/fluid/Sources.h"

#include <array>
#include <vector>

namespace eikon::sim {

struct DiffusionRoles {
    std::vector<DiffusionRole> temperature;
    std::vector<DiffusionRole> scalars;  // concentration and dye
    std::array<std::vector<DiffusionRole>, 3> velocity;
};

DiffusionRoles diffusionRoles(const FluidDomain& domain, const SceneSources& sources, const MacGrid& mac);

}  // namespace eikon::sim
