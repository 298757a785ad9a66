#include "verify/accuracy/CatenaryMap.h"

#include "verify/accuracy/ReceiverCaseScene.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace eikon::accuracy {

namespace {

constexpr double kA = 1.0, kB = 0.25;                             // n = a + b·y
constexpr double kLength = 1.28, kHeight = 0.64, kDepth = 0.16;  // m: the grid
constexpr double kPlaneX = 1.2;                                   // the receiver's plane
constexpr int kRows = 32;

glm::dvec3 beam() { return glm::normalize(glm::dvec3(1.0, -0.2, 0.0)); }

// Row of a height on the receiver (its v axis is −y, so row 0 is at the top).
int rowOf(double y) { return static_cast<int>(std::floor((0.5 - (y - 0.5 * kHeight) / kHeight) * kRows)); }

// Where the ray entering at (x0, y0) along the beam crosses x = kPlaneX, or
// a negative height if it leaves the grid through its bottom or top first.
double landingHeight(double x0, double y0) {
    const glm::dvec3 d = beam();
    const double n0 = kA + kB * y0;
    const double c = n0 * d.x;  // n·cos θ, the invariant
    const double vertexX = x0 + (c / kB) * std::acosh(n0 / c);
    const double vertexY = (c - kA) / kB;
    if (vertexY < 0.0 && vertexX - (c / kB) * std::acosh(kA / c) < kPlaneX) return -1.0;  // reaches the bottom first
    const double y = (c * std::cosh(kB * (kPlaneX - vertexX) / c) - kA) / kB;
    // Past its vertex the ray climbs: it must not have left through the top.
    if (y > kHeight) return -1.0;
    return y;
}

}  // namespace

const reference::LinearSlabField& catenaryMapField() {
    static const reference::LinearSlabField field(kA, kB);
    return field;
}

Scene catenaryMapScene() {
    Scene scene = receiverCaseScene(glm::dvec3(0.0), glm::dvec3(kLength, kHeight, kDepth), glm::ivec3(128, 64, 16), kA);
    scene.lights.push_back(unitBeam(beam()));
    scene.receivers.push_back(
        unfilteredReceiver(glm::dvec3(kPlaneX, 0.5 * kHeight, 0.5 * kDepth), glm::dvec3(-1.0, 0.0, 0.0), kHeight, kRows));
    scene.objects.push_back(coverBox(scene, kA));
    return scene;
}

std::vector<double> catenaryReferenceRows() {
    const glm::dvec3 d = beam();
    std::vector<double> power(kRows, 0.0);  // W per metre of z
    auto follow = [&](double x0, double y0, double flux) {
        const double y = landingHeight(x0, y0);
        if (y < 0.0) return;
        const int row = rowOf(y);
        if (row >= 0 && row < kRows) power[static_cast<std::size_t>(row)] += flux;
    };
    const int sideRays = 200'000, topRays = 400'000;
    for (int k = 0; k < sideRays; ++k) follow(0.0, (k + 0.5) / sideRays * kHeight, d.x * kHeight / sideRays);
    for (int k = 0; k < topRays; ++k) follow((k + 0.5) / topRays * kPlaneX, kHeight, -d.y * kPlaneX / topRays);
    for (double& row : power) row /= kHeight / kRows;
    return power;
}

double catenaryMapError(const std::vector<float>& map, const std::vector<double>& rows) {
    return layeredRowsError(map, rows, kHeight, kDepth, 0.03);
}

}  // namespace eikon::accuracy
