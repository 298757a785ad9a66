// Receivers and photon paths as PolyData for ParaView.
#pragma once

#include "bridge/scene/Scene.h"
#include "io/vtk/PolyDataWriter.h"

#include <glm/vec4.hpp>

#include <vector>

namespace eikon::io {

// Each receiver as its map's texels: a (res + 1)² lattice of points on the
// plane, point ± size/2 along its axes u and v (bridge/scene/ReceiverAxes.h),
// and res² quads (texel (i, j) spans [i, i+1]·size/res along u from the
// square's corner, likewise j along v); in float, as the renderer places them.
// Cell arrays: "irradiance" (RGB, W/m², `irradiance[r]` in the map's order:
// rows along axisV, texels along axisU) and "receiver" (its index).
PolyData receiverQuads(const std::vector<ReceiverDesc>& receivers,
                       const std::vector<std::vector<float>>& irradiance);

// Recorded photon paths (PhotonStage: `verticesPerPhoton` slots per photon,
// xyz with w = 1 where written, and RGB power per slot) as polylines, one per
// photon with at least two vertices; point array "power" (RGB, W).
PolyData photonPolylines(const std::vector<glm::vec4>& vertices, const std::vector<glm::vec4>& power,
                         int verticesPerPhoton);

}  // namespace eikon::io
