// Mouse gestures of the viewer as changes of the camera orbit and of a light:
// plain functions of the drag in pixels, so they are tested without a window.
#pragma once

#include "bridge/scene/Orbit.h"
#include "bridge/scene/Scene.h"

namespace eikon::view {

// Left drag: turn about the target, 0.3° per pixel; elevation kept in (−89°, 89°).
Orbit orbitDrag(Orbit orbit, double dxPixels, double dyPixels);
// Middle drag: move the target in the image plane so the point under the
// cursor stays under it (at the target's depth).
Orbit panDrag(Orbit orbit, const CameraDesc& camera, double dxPixels, double dyPixels, int viewportHeight);
// Wheel: each notch brings the camera 10% closer (negative: farther).
Orbit zoom(Orbit orbit, double notches);
// Right drag: a point or spot light moves in its horizontal plane, along the
// camera's right and forward directions, by the distance the drag covers at
// the light's depth. Directional lights turn instead (0.3° per pixel).
LightDesc lightDrag(LightDesc light, const CameraDesc& camera, double dxPixels, double dyPixels, int viewportHeight);

}  // namespace eikon::view
