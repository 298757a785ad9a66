// Maxwell's fish-eye on a receiver past the image, for either light
// estimator: the accuracy suite's fish-eye (n = 2/(1 + (r/0.5 m)²), a 2 m
// cube of 64³ voxels) and its spot light at P = (0.4, 0, 0) aimed at −x (1 W
// in a 25° cone, hard edge), whose rays all pass through the image
// P′ = −R²P/|P|² = (−0.625, 0, 0) and spread again beyond it onto a receiver
// 0.2 m further (0.24 m square, 64² texels, facing +x). Ground truth from
// the double-precision reference tracer through the analytic field: rings
// of directions about the axis, each of power I·2π·sin θ·dθ, traced to the
// plane (verify/accuracy/RingMap).
#pragma once

#include "bridge/scene/Scene.h"
#include "verify/reference/AnalyticFields.h"

#include <vector>

namespace eikon::accuracy {

const reference::FishEyeField& fishEyeMapField();

// The scene, its receiver unfiltered; an invisible box over the grid makes
// the light fill its cone (light the lens bends onto the receiver would miss
// it otherwise).
Scene fishEyeMapScene();

// Irradiance (W/m²) per texel, j·resolution + i, by the reference tracer.
std::vector<double> fishEyeReferenceMap();

}  // namespace eikon::accuracy
