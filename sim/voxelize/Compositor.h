// Scene objects composited over the medium, in list order by coverage
// ([Sun08] §4.1: fractional coverage → index): for a cell an object
// covers by f, each property p (n, κ, σs, g) becomes f·p_object + (1 − f)·p
// — except the index of a sharp object, which stays out of the field: the
// tracer applies it exactly at the object's surface, so smoothing never
// crosses it.
// Spheres and boxes are covered analytically (AnalyticVoxelizer); meshes
// and water bring their coverage grids (MeshCoverage). The Gaussian
// smoothing of the index that follows runs on the GPU, for fields from any
// source (render/stages/PrepareStage), so none is applied here.
#pragma once

#include "bridge/grid/FieldSet.h"
#include "bridge/grid/FieldViews.h"
#include "bridge/scene/Scene.h"
#include "bridge/grid/CellBox.h"

#include <vector>

namespace eikon::sim {

// Per object of the scene, its coverage grid (one value per cell) when it
// is a mesh or water, nullptr when it is a sphere or a box.
using CoverageGrids = std::vector<const std::vector<float>*>;

// Sets the cells of `region` to the scene's medium (its air temperature
// profile, when it has one); creates κ, σs or g where the medium needs them.
// `fields` must hold δn for every cell.
void fillMedium(const Scene& scene, FieldSet& fields, const CellBox& region);
// The same in memory that already has every field the medium needs.
void fillMedium(const Scene& scene, const FieldViews& fields, const CellBox& region);

// Composites the scene's objects over the fields in `region` (the whole grid
// by default); creates κ, σs or g where an object needs them. Every mesh or
// water object must have its grid in `grids`. Versions are left to the caller.
void paintObjects(const Scene& scene, FieldSet& fields, const CoverageGrids& grids = {},
                  const CellBox* region = nullptr);
// The same in memory that already has every field an object needs (a GPU
// ring slot).
void paintObjects(const Scene& scene, const FieldViews& fields, const CoverageGrids& grids = {},
                  const CellBox* region = nullptr);

}  // namespace eikon::sim
