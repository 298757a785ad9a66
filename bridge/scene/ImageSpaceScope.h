// What the image-space method (render.method "image_space") can show: sharp
// surfaces (spheres, boxes, meshes, the water surface) in a uniform medium,
// with Beer–Lambert extinction inside them. It bends no ray inside a graded
// field and gathers no light from a volume, so it cannot show mirages, heat
// shimmer, smoothed glass, fog, smoke or volume caustics.
#pragma once

#include "bridge/scene/Scene.h"

#include <string>
#include <vector>

namespace eikon {

// What of `scene` image space would drop, one phrase per part ("the sim
// section's fluid (a graded medium)"); empty when it shows the scene whole.
std::vector<std::string> imageSpaceOmissions(const Scene& scene);

// The omissions as one sentence for stderr and the report, or "" when none.
std::string describeImageSpaceOmissions(const Scene& scene);

}  // namespace eikon
