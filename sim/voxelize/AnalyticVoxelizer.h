// Analytic shapes (spheres, boxes) → optical fields on the scene grid.
//
// Follows [Sun08] §4.1: fractional coverage per voxel from
// supersampling (s³ samples, 4³ by default, only in voxels the surface
// crosses); the objects are composited by coverage (Compositor.h).
#pragma once

#include "bridge/grid/FieldSet.h"
#include "bridge/scene/Scene.h"

namespace eikon::sim {

// Fraction of the voxel at `cell` inside `object` (a sphere or a box), in [0, 1].
double coverage(const ObjectDesc& object, const GridSpec& grid, int i, int j, int k, int supersampling);

// n(y) of an air temperature profile (Scene.h) by Gladstone–Dale
// (sim/optics/AirOptics.h).
double airProfileIndex(const AirTemperatureProfile& profile, double y);

// Index, extinction and scattering of a scene's medium, spheres and boxes and
// paint strokes (VolumePainter.h) (a scene with mesh or water objects needs SceneFields). Extinction
// and scattering are left empty when zero everywhere.
FieldSet voxelizeScene(const Scene& scene);

}  // namespace eikon::sim
