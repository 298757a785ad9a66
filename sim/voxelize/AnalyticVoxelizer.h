// Analytic shapes (spheres, boxes) → optical fields on the scene grid.
//
// Follows Sun et al. 2008, §4.1: fractional coverage per voxel from
// supersampling (s³ samples, 4³ by default, only in voxels the surface
// crosses), materials composited in list order by coverage. The Gaussian
// smoothing of the index that follows runs on the GPU, for fields from any
// source (render/stages/PrepareStage).
#pragma once

#include "bridge/grid/FieldSet.h"
#include "bridge/grid/FieldViews.h"
#include "bridge/scene/Scene.h"

#include <vector>

namespace eikon::sim {

// Fraction of the voxel at `cell` inside `object`, in [0, 1].
double coverage(const ObjectDesc& object, const GridSpec& grid, int i, int j, int k, int supersampling);

// n(y) of an air temperature profile (Scene.h) by Gladstone–Dale.
double airProfileIndex(const AirTemperatureProfile& profile, double y);
// δn of the profile, cell-centre heights, into every cell of `fields`.
void writeAirProfile(const AirTemperatureProfile& profile, FieldSet& fields);

// Index, extinction and scattering of the scene's medium, objects and paint
// strokes (VolumePainter.h).
// Extinction and scattering are left empty when zero everywhere.
FieldSet voxelizeScene(const Scene& scene);

// Composites the scene's objects over fields that already hold a medium
// (the fluid solver's, say), in list order by coverage; creates κ, σs or g
// where an object needs them. Versions are left to the caller.
void paintObjects(const Scene& scene, FieldSet& fields);
// The same in place, over memory that already has every field an object needs.
void paintObjects(const Scene& scene, const FieldViews& fields);

}  // namespace eikon::sim
