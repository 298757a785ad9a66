// camera.projection and camera.width_m: a pinhole camera, or parallel rays
// from an image plane of a given width (the diagnostics' parallel light).
#pragma once

#include "bridge/scene/Scene.h"
#include "io/scene/JsonReader.h"

namespace eikon {

// Reads those keys of the camera object into `camera`: width_m is required
// with "orthographic" and refused with "perspective" (it would be unused).
void readCameraProjection(const JsonObjectReader& cameraFields, CameraDesc& camera);

// Throws InputError at camera.projection where image space, whose surface
// layers are drawn from a viewpoint, is asked for an orthographic view.
void checkCameraProjection(const JsonObjectReader& sceneFields, const Scene& scene);

}  // namespace eikon
