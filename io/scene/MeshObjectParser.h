// The scene objects of type "mesh" and "water" (docs/scene-format.md):
// shape, placement and deformer keys. The material keys (index,
// extinction, scattering, anisotropy) are read by the caller's
// `readMaterial`, as for spheres and boxes.
#pragma once

#include "io/scene/JsonReader.h"
#include "bridge/scene/Scene.h"

#include <functional>
#include <string>

namespace eikon {

using MaterialReader = std::function<void(const JsonObjectReader&, Material&)>;

// `type` is the object's "type", already read: "mesh" or "water". Mesh paths
// are resolved against `sceneFolder`.
ObjectDesc readMeshOrWaterObject(const JsonReader& node, const std::string& type, const std::string& sceneFolder,
                                 const MaterialReader& readMaterial);

}  // namespace eikon
