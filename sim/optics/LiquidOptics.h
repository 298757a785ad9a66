// Index of a mixture of two liquids, A (concentration 0) and B (1), with c the
// volume fraction of B (ideal mixing: volumes add).
//   linear:          n = (1 − c)·n_A + c·n_B  (Arago–Biot)
//   Lorentz–Lorenz:  (n² − 1)/(n² + 2) = (1 − c)·R_A + c·R_B,  R = (n² − 1)/(n² + 2)
// ([Born99] §2.3.3, eq. 2.3.18 for the molar refractivity, which is additive
// over components). For sucrose syrup diluted in water the linear rule in
// volume fraction reproduces the sucrose refractometry table ([ICUMSA])
// within 5e-4 (tests/unit/test_optics.cpp).
#pragma once

#include "bridge/scene/Scene.h"

namespace eikon::sim {

double lorentzLorenzRefraction(double index);       // R = (n² − 1)/(n² + 2)
double indexFromLorentzLorenz(double refraction);   // n = sqrt((1 + 2R)/(1 − R))

// n of the mixture; c is clamped to [0, 1].
double mixedIndex(double indexA, double indexB, double concentration, SimDesc::Mixing rule);

}  // namespace eikon::sim
