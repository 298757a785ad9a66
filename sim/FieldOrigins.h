// The key paths behind each optical field of a scene, for a refused value
// (bridge/grid/FieldSet.h, validateFields): a user reads which keys of which
// file to change, and where, never only an internal cell.
#pragma once

#include "bridge/grid/FieldSet.h"
#include "bridge/scene/Scene.h"

#include <string>

namespace eikon::sim {

// The scene file and the keys that set a field: the strokes that reach the
// refused value, the solver's or the volume's optics (with `volumeFile`, the
// file of the current frame), the air profile, then the medium. Objects are
// left out: each mixes its own bounded values in by its coverage, which never
// leaves a field's range.
FieldOrigin sceneFieldOrigin(const Scene& scene, const std::string& volumeFile = "");

}  // namespace eikon::sim
