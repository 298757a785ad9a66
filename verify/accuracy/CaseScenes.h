// The small scenes the accuracy cases (and the tracer tests) are built from:
// an empty grid box with an 8×8 image (only photons matter), and a square
// receiver on the floor facing up.
#pragma once

#include "bridge/scene/Scene.h"

namespace eikon::accuracy {

inline Scene boxScene(glm::dvec3 boundsMin, glm::dvec3 boundsMax) {
    Scene scene;
    scene.grid.boundsMin = boundsMin;
    scene.grid.boundsMax = boundsMax;
    scene.render.width = 8;
    scene.render.height = 8;
    return scene;
}

inline ReceiverDesc floorReceiver(double y, double size, int resolution) {
    ReceiverDesc receiver;
    receiver.point = glm::dvec3(0.0, y, 0.0);
    receiver.normal = glm::dvec3(0.0, 1.0, 0.0);
    receiver.size = size;
    receiver.resolution = resolution;
    return receiver;
}

}  // namespace eikon::accuracy
