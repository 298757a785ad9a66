// The `export` and `volume` sections of scene files (docs/scene-format.md).
// Kept apart from SceneParser.cpp: each reads one section and throws
// InputError at the JSON path of the offending value.
#pragma once

#include "io/scene/JsonReader.h"
#include "bridge/scene/Scene.h"

#include <string>

namespace eikon {

// `export`: {"vtk": {...}, "vdb": {...}} into scene.exports. Checks that the
// fields listed exist in this scene (velocity needs a sim or a volume with a
// velocity grid, …) and turns on what they need (fluence storage for fluence
// and photon_direction), so call it after every other section.
void readExport(const JsonReader& node, Scene& scene);

// `volume`: an OpenVDB file or sequence, or VTK data; the (first) file must exist.
VolumeDesc readVolume(const JsonReader& node, const std::string& sceneFolder);

}  // namespace eikon
