// Ground truth for the showcase: a point light (or a parallel beam) above a
// sharp glass sphere over a square diffuse receiver, the receiver's
// irradiance per texel by Monte Carlo over exact ray–sphere intersections
// with Snell refraction, total internal reflection and (optionally)
// unpolarised Fresnel splitting, in double precision (SphereOptics). It shares no code with the GPU path — no voxels, no
// shaders, no emission or receiver code of the renderer — so it can find the
// renderer's model errors as well as its tracer's. For tests only.
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace eikon::reference {

struct SphereCausticSetup {
    glm::dvec3 light{0.0, 1.8, 0.0};  // point light, isotropic
    double power = 1.0;               // W (one channel)
    glm::dvec3 centre{0.0, 0.55, 0.0};
    double radius = 0.25;
    double sphereIndex = 1.5;
    double mediumIndex = 1.0;
    bool fresnel = true;              // false: every crossing transmits (except total internal reflection)
    // false: the Fresnel-reflected branches are dropped, the transmitted light
    // keeping its 1 − R (what the wavefront estimator follows).
    bool followReflections = true;
    // The receiver: the square of edge `size` centred at `receiverCentre` in
    // the plane y = receiverCentre.y, lit from above (+y), texels along x and z.
    glm::dvec3 receiverCentre{0.0, 0.02, 0.0};
    double size = 2.4;
    int resolution = 192;
    long long rays = 4'000'000;       // sampled uniformly in the cone from the light over the receiver
    std::uint64_t seed = 1;
    int maxCrossings = 12;            // surface events per path; what remains after is dropped (≪ 1e-6 of the power)
};

struct IrradianceMap {
    int resolution = 0;
    double size = 0.0;
    std::vector<double> irradiance;  // W/m², texel (i along x, j along z) at j·resolution + i

    double at(int i, int j) const { return irradiance[static_cast<std::size_t>(j) * resolution + i]; }
};

IrradianceMap traceSphereCaustic(const SphereCausticSetup& setup);

// The same map without noise, for a light, sphere and receiver centre on one
// vertical axis and an even resolution (std::invalid_argument otherwise): the
// irradiance is then a function of the distance from the axis, so rays in one
// meridian plane suffice. `angles` rings of directions about the axis, each
// of power I·2π·sin θ·dθ (midpoint rule in θ up to the cone of the receiver's
// corners), follow the same exact ray tree as traceSphereCaustic (Snell,
// total internal reflection, Fresnel splitting), and each ring's power lands
// on the circle it reaches, shared among the texels by the length of circle
// inside each. The error is the quadrature's, far below a texel per ring
// (`rays` and `seed` are unused).
IrradianceMap integrateSphereCaustic(const SphereCausticSetup& setup, long long angles = 400'000);

// The same noise-free map under a parallel beam of `irradiance` W/m²
// travelling along −y in place of the point light (`light`, `power`, `rays`
// and `seed` unused), for a sphere and receiver centre on one vertical axis
// and an even resolution (std::invalid_argument otherwise): `rings` rings of
// impact parameter b about the axis, each of power E·2πb·db (midpoint rule
// in b out to the sphere's radius or the receiver's corners, whichever is
// further), follow the same exact ray tree.
IrradianceMap integrateSphereCausticUnderBeam(const SphereCausticSetup& setup, double irradiance,
                                              long long rings = 400'000);

// The radius on the receiver plane of the sphere's geometric shadow from the
// light: h·tan(asin(R/d)) with h the light's height above the plane and d its
// distance from the centre (light straight above the centre).
double shadowRadius(const SphereCausticSetup& setup);

}  // namespace eikon::reference
