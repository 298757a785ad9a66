// The mirage on a receiver, for either light estimator: the accuracy suite's
// exponential layer n = 1.05 − 0.05·exp(−y/0.1 m) over 2.56 × 0.48 × 0.64 m
// under a beam along (1, −0.15, 0), seen on a receiver across the far end
// (x = 2.4 m, 48 rows of 1 cm). Ground truth from the double-precision
// reference tracer: the problem is uniform along z, so a dense fan of
// reference rays through the grid's x = 0 and top faces, each carrying the
// beam's flux through its strip of face, binned by where it crosses the
// receiver's plane, gives each row's irradiance.
#pragma once

#include "bridge/scene/Scene.h"
#include "verify/reference/AnalyticFields.h"

#include <vector>

namespace eikon::accuracy {

const reference::MirageField& mirageMapField();

// The scene, 1 cm voxels (256×48×64), its receiver unfiltered; an invisible
// box over the grid makes the light cover it all (the sampled field is not a
// scene object, and light bent onto the receiver would miss it otherwise).
Scene mirageMapScene();

// Irradiance (W/m²) of each receiver row (row 0 at the top: the receiver's
// v axis is −y), by the reference tracer.
std::vector<double> mirageReferenceRows();

// Relative L1 of a receiver map (RGB per texel, green compared) against the
// rows, over the texels more than 4 cm inside the grid's z faces.
double mirageMapError(const std::vector<float>& map, const std::vector<double>& rows);

}  // namespace eikon::accuracy
