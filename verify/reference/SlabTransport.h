// Ground truth for multiple scattering: analog Monte Carlo of light in a
// homogeneous plane-parallel slab with index-matched faces (no refraction,
// no Fresnel), the volumetric path tracing a lattice or diffusion method
// must agree with. A collimated beam meets the face z = 0 at normal
// incidence; each photon flies exponential free paths of mean 1/μt, and at
// each collision scatters with probability albedo = μs/μt — isotropically,
// or by Henyey–Greenstein with asymmetry g — or is absorbed. Every photon
// ends in exactly one of: reflected (back out of z = 0), transmitted
// diffusely (out of z = L after scattering), transmitted directly (never
// scattered) or absorbed, so the four fractions sum to 1 exactly. Double
// precision, seeded, on the CPU; it shares no code with the renderer. For
// tests only.
#pragma once

#include <cstdint>

namespace eikon::reference {

struct SlabSetup {
    double opticalThickness = 1.0;  // τ = μt·L, > 0
    double albedo = 0.9;            // μs/μt in [0, 1]
    double anisotropy = 0.0;        // Henyey–Greenstein g in (−1, 1)
    long long photons = 100000;
    std::uint64_t seed = 1;
};

// Fractions of the beam's power, each with its binomial standard error.
struct SlabFractions {
    double reflected = 0.0, diffuselyTransmitted = 0.0, directlyTransmitted = 0.0, absorbed = 0.0;
    double reflectedError = 0.0, diffuselyTransmittedError = 0.0;
    double meanCollisions = 0.0;  // per photon
};

SlabFractions traceSlab(const SlabSetup& setup);

}  // namespace eikon::reference
