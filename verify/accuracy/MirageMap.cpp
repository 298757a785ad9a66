#include "verify/accuracy/MirageMap.h"

#include "verify/accuracy/ReceiverCaseScene.h"

#include "verify/reference/ReferenceTracer.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace eikon::accuracy {

namespace {

constexpr double kLength = 2.56, kHeight = 0.48, kDepth = 0.64;  // m: the grid
constexpr double kPlaneX = 2.4;                                   // the receiver's plane
constexpr int kRows = 48;

glm::dvec3 beam() { return glm::normalize(glm::dvec3(1.0, -0.15, 0.0)); }

// Row of a height on the receiver (its v axis is −y, so row 0 is at the top).
int rowOf(double y) { return static_cast<int>(std::floor((0.5 - (y - 0.5 * kHeight) / kHeight) * kRows)); }

}  // namespace

const reference::MirageField& mirageMapField() {
    static const reference::MirageField field(1.05, 0.05, 0.1);
    return field;
}

Scene mirageMapScene() {
    Scene scene = receiverCaseScene(glm::dvec3(0.0), glm::dvec3(kLength, kHeight, kDepth), glm::ivec3(256, 48, 64), 1.05);
    scene.lights.push_back(unitBeam(beam()));
    scene.receivers.push_back(
        unfilteredReceiver(glm::dvec3(kPlaneX, 0.5 * kHeight, 0.5 * kDepth), glm::dvec3(-1.0, 0.0, 0.0), kHeight, kRows));
    scene.objects.push_back(coverBox(scene, scene.medium.index));
    return scene;
}

std::vector<double> mirageReferenceRows() {
    reference::ReferenceOptions options;
    options.tolerance = 1e-10;
    const reference::ReferenceTracer tracer(mirageMapField(), options);
    const glm::dvec3 d = beam();
    std::vector<double> power(kRows, 0.0);  // W per metre of z
    auto follow = [&](glm::dvec3 entry, double flux) {
        const reference::ReferenceResult result =
            tracer.trace(tracer.start(entry, d), 10.0, [](const reference::RayState& s) {
                return std::min({kPlaneX - s.x.x, s.x.y, kHeight - s.x.y});
            });
        if (!result.eventHit || std::abs(result.state.x.x - kPlaneX) > 1e-7) return;  // left the grid first
        const int row = rowOf(result.state.x.y);
        if (row >= 0 && row < kRows) power[static_cast<std::size_t>(row)] += flux;
    };
    const int sideRays = 24'000, topRays = 60'000;
    for (int k = 0; k < sideRays; ++k)
        follow({0.0, (k + 0.5) / sideRays * kHeight, 0.5 * kDepth}, d.x * kHeight / sideRays);
    for (int k = 0; k < topRays; ++k)
        follow({(k + 0.5) / topRays * kPlaneX, kHeight - 1e-9, 0.5 * kDepth}, -d.y * kPlaneX / topRays);
    for (double& row : power) row /= kHeight / kRows;
    return power;
}

double mirageMapError(const std::vector<float>& map, const std::vector<double>& rows) {
    return layeredRowsError(map, rows, kHeight, kDepth, 0.04);
}

}  // namespace eikon::accuracy
