// The top-level `diagnostic` section (bridge/scene/DiagnosticDesc.h): an
// interferometer or a schlieren system looking through the scene in place
// of the camera's picture.
#pragma once

#include "bridge/scene/Scene.h"
#include "io/scene/JsonReader.h"

namespace eikon {

// The section; each type takes only its own keys.
DiagnosticDesc readDiagnostic(const JsonReader& node);

// Once the whole scene is read, where a diagnostic is set: the camera must
// be orthographic (the light is parallel), the method eikonal, every object
// smooth (the diagnostics trace graded fields, not sharp surfaces), and a
// tilted reference beam's fringes at least two pixels apart. InputError at
// the key that breaks it.
void checkDiagnostic(const JsonObjectReader& sceneFields, const Scene& scene);

}  // namespace eikon
