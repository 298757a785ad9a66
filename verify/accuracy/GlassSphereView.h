// The accuracy suite's glass sphere (n = 1.5, R = 0.25 m; GlassSphereMap's
// sharp sphere) seen in image space (render.method "image_space") by a
// camera 2 m above it on its axis, looking down along the glass_sphere
// case's beam: each pixel's exit direction against the exact two-interface
// ray (reference::transitSphere), scored as glass_sphere_reference scores
// the photons — where the exit ray crosses the paraxial focal plane (0.375 m
// below the centre), its distance from the exact ray's crossing over R, RMS
// over the pixels whose ray passes within 0.8 R of the centre. The view
// records only directions, so both rays leave from the exact exit point:
// the measure is of the direction alone.
#pragma once

#include "bridge/scene/Scene.h"
#include "verify/accuracy/AccuracyRun.h"

#include <glm/vec4.hpp>

#include <vector>

namespace eikon::accuracy {

// The sphere and the camera, drawing a square image of `pixels` per edge.
Scene glassSphereViewScene(int pixels);

// The measure of `exits` (ImageSpaceView::downloadExits) of that scene.
Measurement glassSphereViewError(const Scene& scene, const std::vector<glm::vec4>& exits);

}  // namespace eikon::accuracy
