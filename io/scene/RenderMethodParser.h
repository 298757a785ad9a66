// render.method and render.method_fallback: which image formation draws the
// scene, and whether image space may draw a scene it cannot show whole
// (bridge/scene/ImageSpaceScope.h); and render.caustic_map_texels, image
// space's photons per light.
#pragma once

#include "bridge/scene/Scene.h"
#include "io/scene/JsonReader.h"

namespace eikon {

// Reads those keys of the render object into `render`.
void readRenderMethod(const JsonObjectReader& renderFields, RenderDesc& render);

// Throws InputError at render.method where image space is asked for a scene
// with media it would drop and render.method_fallback does not allow it.
void checkRenderMethod(const JsonObjectReader& sceneFields, const Scene& scene);

}  // namespace eikon
