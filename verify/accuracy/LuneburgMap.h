// The Luneburg lens on a receiver past its focus, for either light
// estimator: n = √(2 − (r/R)²), R = 0.4 m, sampled on a 1 m cube of 64³
// voxels, lit by a beam of 1 W/m² along +z. Every ray of impact parameter b
// leaves the lens through its focus (0, 0, R) at θ = asin(b/R) from the axis
// (Luneburg 1944), so on the plane z = R + D it lands at ρ = D·tan θ and
// carries the beam's flux of its annulus there: the irradiance is
//   E(ρ) = E0·R²·D² / (ρ² + D²)²,
// in closed form, which the sampled field's march must reproduce.
#pragma once

#include "bridge/scene/Scene.h"
#include "verify/reference/AnalyticFields.h"

#include <vector>

namespace eikon::accuracy {

const reference::LuneburgField& luneburgMapField();

// The scene, its receiver (0.5 m square of 32² texels at D = 0.2 m, facing
// the lens; every texel within the focus's cone, none lit directly)
// unfiltered; an invisible sphere over the lens makes the light cover it.
Scene luneburgMapScene();

// E(ρ) averaged over each texel, j·resolution + i, by an 8×8 midpoint rule.
std::vector<double> luneburgMapTexelMeans();

}  // namespace eikon::accuracy
