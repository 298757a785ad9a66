// A linear-gradient slab's catenaries on a receiver, for either light
// estimator: n = 1 + 0.25·y over 1.28 × 0.64 × 0.16 m (1 cm voxels), under a
// beam along (1, −0.2, 0), seen on a receiver across the far end (x = 1.2 m,
// 32 rows of 2 cm). In a layered medium n·cos θ = C along a ray, and for
// n = a + b·y its path is the catenary n(y(x)) = C·cosh(b·(x − x_v)/C)
// (x_v = x0 + (C/b)·acosh(n0/C) for a ray entering at (x0, y0) heading
// down), so where every entry point lands on the receiver is a closed form;
// a dense fan of entry points through the grid's x = 0 and top faces, each
// carrying the beam's flux through its strip of face, binned by landing row,
// gives each row's irradiance.
#pragma once

#include "bridge/scene/Scene.h"
#include "verify/reference/AnalyticFields.h"

#include <vector>

namespace eikon::accuracy {

const reference::LinearSlabField& catenaryMapField();

// The scene, its receiver unfiltered; an invisible box over the grid makes
// the light cover it.
Scene catenaryMapScene();

// Irradiance (W/m²) of each receiver row (row 0 at the top: the receiver's
// v axis is −y), by the closed-form catenaries.
std::vector<double> catenaryReferenceRows();

// Relative L1 of a receiver map (RGB per texel, green compared) against the
// rows, over the texels more than 3 cm inside the grid's z faces.
double catenaryMapError(const std::vector<float>& map, const std::vector<double>& rows);

}  // namespace eikon::accuracy
