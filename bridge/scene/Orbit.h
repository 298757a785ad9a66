// Orbit parameters for interactive cameras (the viewer drives these): the
// camera sits at `distance` from `target`, at `azimuthDeg` about +y
// (0 looks along −z) and `elevationDeg` above the horizontal plane.
#pragma once

#include "bridge/scene/Scene.h"

namespace eikon {

struct Orbit {
    glm::dvec3 target{0.0};
    double distance = 1.0;      // > 0
    double azimuthDeg = 0.0;
    double elevationDeg = 0.0;  // in (−90, 90)
};

// The orbit that reproduces `camera` (its up vector is taken as +y).
Orbit orbitOf(const CameraDesc& camera);

// A camera on the orbit with +y up, keeping the field of view of `base`.
CameraDesc cameraOn(const Orbit& orbit, const CameraDesc& base);

}  // namespace eikon
