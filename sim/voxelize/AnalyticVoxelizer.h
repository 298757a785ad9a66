// Analytic shapes (spheres, boxes) → optical fields on the scene grid.
//
// Follows Sun et al. 2008, §4.1: fractional coverage per voxel from
// supersampling (s³ samples, 4³ by default, only in voxels the surface
// crosses), materials composited in list order by coverage, then the index
// smoothed with a Gaussian (default σ = 1.5 voxels in a 9³ window) so that
// ∇n is finite and rays bend smoothly across interfaces.
#pragma once

#include "bridge/grid/FieldSet.h"
#include "bridge/scene/Scene.h"

#include <vector>

namespace eikon::sim {

// Fraction of the voxel at `cell` inside `object`, in [0, 1].
double coverage(const ObjectDesc& object, const GridSpec& grid, int i, int j, int k, int supersampling);

// Index, extinction and scattering of the scene's medium and objects.
// Extinction and scattering are left empty when zero everywhere.
FieldSet voxelizeScene(const Scene& scene);

}  // namespace eikon::sim
