// A receiver map without noise for a scene symmetric about an axis normal
// to the receiver, by the reference tracer: rings of rays, each ray standing
// for its ring's power, traced to the receiver's plane and shared among the
// texels by the length of the circle it lands on inside each
// (reference::CircleDeposit). The accuracy suite's glass sphere and fish-eye
// receiver cases. For tests only.
#pragma once

#include "verify/reference/IndexField.h"
#include "verify/reference/ReferenceTracer.h"

#include <functional>
#include <vector>

namespace eikon::accuracy {

// Ring k of a map: its ray's start and unit direction, and its power (W).
struct RingRay {
    glm::dvec3 start{0.0};
    glm::dvec3 direction{0.0};
    double power = 0.0;
};

struct RingMapSetup {
    int rings = 0;
    std::function<RingRay(int ring)> ray;
    reference::RayEvent plane;                        // zero on the receiver's plane, positive before it
    std::function<double(const glm::dvec3&)> radius;  // distance of a point on the plane from the axis
    int texels = 0;                                   // per edge of the square receiver, even
    double size = 0.0;                                // m: the receiver's edge
};

// Irradiance (W/m²) per texel, j·texels + i, centred on the axis.
std::vector<double> ringMap(const reference::IndexField& field, const reference::ReferenceOptions& options,
                            const RingMapSetup& setup);

}  // namespace eikon::accuracy
