#pragma once
// A body force given at cell centres, added to the free faces of a MAC grid:
// each face along `axis` gains scale · ½(f(lower cell) + f(upper cell)), an
// open face at the box's edge its one inside cell's value; fixed faces
// (walls, solid cells) are left as they are. Buoyancy (Sources.cpp) and
// vorticity confinement (VorticityConfinement.cpp) both act this way.
#include "sim/fluid/Boundaries.h"
#include "sim/fluid/MacGrid.h"

#include <tbb/parallel_for.h>

#include <glm/vec3.hpp>

namespace eikon::sim {

// cellForce(i, j, k): the force's component along `axis` at that cell.
template <typename CellForce>
void addCellForceOnFaces(GridField& faceVelocity, const FluidDomain& domain, int axis, double scale,
                         CellForce&& cellForce) {
    tbb::parallel_for(0, faceVelocity.size.z, [&](int k) {
        for (int j = 0; j < faceVelocity.size.y; ++j)
            for (int i = 0; i < faceVelocity.size.x; ++i) {
                if (domain.faceIsFixed(axis, i, j, k)) continue;
                glm::ivec3 upper(i, j, k);
                glm::ivec3 lower = upper;
                lower[axis] -= 1;
                if (lower[axis] < 0) lower = upper;  // an open face sees its one inside cell
                if (upper[axis] >= domain.cells[axis]) upper = lower;
                faceVelocity(i, j, k) +=
                    scale * (0.5 * (cellForce(lower.x, lower.y, lower.z) + cellForce(upper.x, upper.y, upper.z)));
            }
    });
}

}  // namespace eikon::sim
