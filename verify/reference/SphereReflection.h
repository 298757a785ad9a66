// The light a sharp sphere reflects at its first surface (the external
// Fresnel reflection) from a point light on the vertical axis through its
// centre: the whole reflected power, and the part that lands on a square
// receiver below, centred on the same axis. Exact ray optics (SphereOptics)
// in double precision, integrated ring by ring about the axis in the angle
// of incidence, whose steep grazing reflectance at the sphere's rim the
// substitution resolves. Shares no code with the renderer. For tests only.
#pragma once

#include "verify/reference/SphereCaustic.h"

namespace eikon::reference {

struct SphereReflection {
    double reflected = 0.0;   // W reflected at the first surface, all directions
    double onReceiver = 0.0;  // W of it reaching the receiver's square from above
};

// For setup's light, sphere and receiver (light, centre and receiver centre
// on one vertical axis: std::invalid_argument otherwise); `rings` midpoint
// rings in the angle of incidence from 0 to 90°.
SphereReflection integrateFirstSurfaceReflection(const SphereCausticSetup& setup, long long rings = 200'000);

}  // namespace eikon::reference
