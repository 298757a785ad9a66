// The parts the accuracy suite's receiver cases share: a scene of one
// sampled index grid with no objects of its own, a beam, an unfiltered receiver, an
// invisible cover object that makes the light cover what the field bends
// onto the receiver (the sampled field is not a scene object, and the
// emission region is built from objects and receivers), and the relative L1
// of a map against a ground truth per texel or per row.
#pragma once

#include "bridge/scene/Scene.h"

#include <vector>

namespace eikon::accuracy {

// A grid over [boundsMin, boundsMax] of `resolution` voxels in a medium of
// `index`, unsmoothed, a tiny image and 2²¹ photons; lights, receivers and
// cover to be added.
Scene receiverCaseScene(glm::dvec3 boundsMin, glm::dvec3 boundsMax, glm::ivec3 resolution, double index);

// A directional light of 1 W/m² travelling along the unit `direction`.
LightDesc unitBeam(glm::dvec3 direction);

// A square receiver centred at `point` facing `normal`, with no filter.
ReceiverDesc unfilteredReceiver(glm::dvec3 point, glm::dvec3 normal, double size, int resolution);

// Invisible (index `index`, smooth) covers: the grid's box, or a sphere.
ObjectDesc coverBox(const Scene& scene, double index);
ObjectDesc coverSphere(glm::dvec3 centre, double radius, double index);

// Relative L1 of a receiver map (RGB per texel, green compared) against a
// ground truth of one value per texel.
double texelMapError(const std::vector<float>& map, const std::vector<double>& truth);

// Relative L1 of a receiver map (RGB per texel, green compared) across the
// far end of a layered grid of depth `depth` (m, along z) against each row's
// irradiance, over the texels of a receiver of edge `size` centred on the
// grid in z that lie more than `margin` inside its z faces (texel i along
// the receiver's u axis, −z).
double layeredRowsError(const std::vector<float>& map, const std::vector<double>& rows, double size, double depth,
                        double margin);

}  // namespace eikon::accuracy
