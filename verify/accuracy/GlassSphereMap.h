// The smoothed glass sphere's focus on a receiver, for either light
// estimator: the accuracy suite's sphere (n = 1.5, R = 0.25 m, surface
// smoothed by a Gaussian of one voxel, a 0.7 m cube of 64³ voxels) under a
// beam of 1 W/m² along −y, on a receiver in its paraxial focal plane
// (0.375 m below the centre: 0.2 m square, 64² texels). Ground truth from the
// double-precision reference tracer through the same analytic field: the
// map depends only on the distance from the axis, so rings of impact
// parameter b, each of power E0·2πb·db, traced to the plane give it without
// noise (verify/accuracy/RingMap). And the sharp sphere the field smooths,
// for image space, against the exact sphere.
#pragma once

#include "bridge/scene/Scene.h"
#include "verify/reference/AnalyticFields.h"

#include <vector>

namespace eikon::accuracy {

const reference::GlassSphereField& glassSphereMapField();

// The scene, its receiver unfiltered; an invisible sphere over the smoothed
// glass makes the light cover it.
Scene glassSphereMapScene();

// Irradiance (W/m²) per texel, j·resolution + i, by the reference tracer.
std::vector<double> glassSphereReferenceMap();

// The same sphere sharp, as image space draws it (render.method
// "image_space", which cannot draw smoothed glass).
ObjectDesc sharpGlassSphere();

// The scene with the sharp sphere in place of the smoothed field, drawn in
// image space with caustic maps of `causticMapTexels` texels per edge.
Scene sharpGlassSphereMapScene(int causticMapTexels);

// Irradiance (W/m²) per texel under the sharp sphere, noise-free from the
// exact sphere's ray tree (reference::integrateSphereCausticUnderBeam: Snell,
// Fresnel splitting, total internal reflection, in double precision).
std::vector<double> sharpGlassSphereReferenceMap();

}  // namespace eikon::accuracy
