// `grid.fit`: "volume" sizes the render grid to an imported volume — its
// bounds become the box of the active voxels of the volume's first file
// (frame_start), in the scene's world (io/vdb/VolumePlacement.h), with the
// resolution as given. Kept apart from SceneParser.cpp: the grid section is
// read before the volume it depends on.
#pragma once

#include "bridge/scene/Scene.h"
#include "io/scene/JsonReader.h"

namespace eikon {

// Reads grid.fit ("none" or "volume"); "volume" beside grid.bounds is
// refused (both would set the bounds). Returns whether to fit.
bool readGridFit(const JsonObjectReader& grid);

// Sets scene.grid's bounds to the box of the volume's active voxels; call
// once the volume section is read. InputError at grid.fit where the scene
// has no volume or its file says nothing of where its voxels are.
void fitGridToVolume(const JsonReader& fit, Scene& scene);

}  // namespace eikon
