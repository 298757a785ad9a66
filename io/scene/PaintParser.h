// The `paint` list of a scene file: volume-painting strokes
// (docs/scene-format.md, "paint").
#pragma once

#include "io/scene/JsonReader.h"
#include "bridge/scene/Scene.h"

namespace eikon {

// Throws InputError at the JSON path of the first bad value.
PaintStroke readPaintStroke(const JsonReader& node);

}  // namespace eikon
