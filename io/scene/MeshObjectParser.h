// The scene objects of type "mesh" and "water" (docs/scene-format.md):
// shape, placement and deformer keys. The material and surface keys (index,
// extinction, scattering, anisotropy, surface, fresnel) are read by the
// caller's `readProperties`, as for spheres and boxes.
#pragma once

#include "io/scene/JsonReader.h"
#include "bridge/scene/Scene.h"

#include <functional>
#include <string>

namespace eikon {

using PropertiesReader = std::function<void(const JsonObjectReader&, ObjectDesc&)>;

// `type` is the object's "type", already read: "mesh" or "water". Mesh paths
// are resolved against `sceneFolder`.
ObjectDesc readMeshOrWaterObject(const JsonReader& node, const std::string& type, const std::string& sceneFolder,
                                 const PropertiesReader& readProperties);

}  // namespace eikon
