// Ground truth for multiple scattering: analog Monte Carlo of light in a
// homogeneous plane-parallel slab, the volumetric path tracing a lattice or
// diffusion method must agree with. A collimated beam enters the face
// z = 0 at normal incidence (fractions are of the power that entered);
// each photon flies exponential free paths of mean 1/μt, and at each
// collision scatters with probability albedo = μs/μt — isotropically, or by
// Henyey–Greenstein with asymmetry g — or is absorbed. The faces are
// index-matched, or, with a relative index m = n_slab/n_outside ≠ 1, smooth
// dielectric faces: a photon meeting one is reflected specularly with the
// unpolarized Fresnel reflectance at its angle (total internal reflection
// past the critical angle) and otherwise leaves. Every photon ends in
// exactly one of: reflected diffusely (out of z = 0 after scattering),
// transmitted diffusely (out of z = L after scattering), transmitted or
// reflected directly (never scattered) or absorbed, so the five fractions
// sum to 1 exactly. Double precision, seeded, on the CPU; it shares no code
// with the renderer. For tests only.
#pragma once

#include <cstdint>

namespace eikon::reference {

struct SlabSetup {
    double opticalThickness = 1.0;  // τ = μt·L, > 0
    double albedo = 0.9;            // μs/μt in [0, 1]
    double anisotropy = 0.0;        // Henyey–Greenstein g in (−1, 1)
    double relativeIndex = 1.0;     // n_slab/n_outside, > 0; 1: index-matched faces
    long long photons = 100000;
    std::uint64_t seed = 1;
};

// Fractions of the beam's power, each with its binomial standard error.
struct SlabFractions {
    double reflected = 0.0, diffuselyTransmitted = 0.0, directlyTransmitted = 0.0, absorbed = 0.0;
    double directlyReflected = 0.0;  // the unscattered beam back out of z = 0 (only with Fresnel faces)
    double reflectedError = 0.0, diffuselyTransmittedError = 0.0;
    double meanCollisions = 0.0;  // per photon
};

SlabFractions traceSlab(const SlabSetup& setup);

// The unpolarized Fresnel reflectance of light meeting a smooth interface
// from the side of index n_from at cos θ = cosIncidence to the normal: 1
// past the critical angle.
double fresnelReflectance(double cosIncidence, double nFrom, double nTo);

}  // namespace eikon::reference
