// The top-level `diagnostic` section (bridge/scene/DiagnosticDesc.h): an
// interferometer, a schlieren system, a shadowgraph or background-oriented
// schlieren looking through the scene in place of the camera's picture.
#pragma once

#include "bridge/scene/Scene.h"
#include "io/scene/JsonReader.h"

#include <string>

namespace eikon {

// The section; each type takes only its own keys. BOS's image pattern is
// read here, its path relative to sceneFolder.
DiagnosticDesc readDiagnostic(const JsonReader& node, const std::string& sceneFolder);

// Once the whole scene is read, where a diagnostic is set: the camera must
// be orthographic (the light is parallel; BOS: perspective), the method
// eikonal, and a tilted reference beam's fringes at least two pixels
// apart. InputError at
// the key that breaks it.
void checkDiagnostic(const JsonObjectReader& sceneFields, const Scene& scene);

}  // namespace eikon
