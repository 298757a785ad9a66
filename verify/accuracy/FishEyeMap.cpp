#include "verify/accuracy/FishEyeMap.h"

#include "verify/accuracy/ReceiverCaseScene.h"
#include "verify/accuracy/RingMap.h"

#include <glm/trigonometric.hpp>

#include <cmath>
#include <numbers>

namespace eikon::accuracy {

namespace {

constexpr double kCone = 25.0;     // degrees: the spot's half-angle
constexpr double kBeyond = 0.2;    // m: the receiver's plane past the image
constexpr double kSize = 0.24;     // m: the receiver's edge
constexpr int kTexels = 64;
constexpr int kRings = 20'000;

glm::dvec3 source() { return {0.4, 0.0, 0.0}; }
double planeX() { return fishEyeMapField().image(source()).x - kBeyond; }

}  // namespace

const reference::FishEyeField& fishEyeMapField() {
    static const reference::FishEyeField field(2.0, 0.5);
    return field;
}

Scene fishEyeMapScene() {
    Scene scene = receiverCaseScene(glm::dvec3(-1.0), glm::dvec3(1.0), glm::ivec3(64), 1.0);
    LightDesc spot;
    spot.kind = LightDesc::Kind::Spot;
    spot.position = source();
    spot.direction = glm::dvec3(-1.0, 0.0, 0.0);
    spot.power = Rgb(1.0);
    spot.coneAngleDeg = kCone;
    spot.falloffDeg = 0.0;
    scene.lights.push_back(spot);
    scene.receivers.push_back(unfilteredReceiver(glm::dvec3(planeX(), 0.0, 0.0), glm::dvec3(1.0, 0.0, 0.0), kSize, kTexels));
    scene.objects.push_back(coverBox(scene, 1.0));
    return scene;
}

std::vector<double> fishEyeReferenceMap() {
    const double cosCone = std::cos(glm::radians(kCone));
    const double intensity = 1.0 / (2.0 * std::numbers::pi * (1.0 - cosCone));  // W/sr: 1 W in the cone
    const double dTheta = glm::radians(kCone) / kRings;
    const double plane = planeX();
    RingMapSetup setup;
    setup.rings = kRings;
    setup.ray = [=](int k) {
        const double theta = (k + 0.5) * dTheta;
        return RingRay{source(), glm::dvec3(-std::cos(theta), std::sin(theta), 0.0),
                       intensity * 2.0 * std::numbers::pi * std::sin(theta) * dTheta};
    };
    setup.plane = [=](const reference::RayState& s) { return s.x.x - plane; };
    setup.radius = [](const glm::dvec3& x) { return std::hypot(x.y, x.z); };
    setup.texels = kTexels;
    setup.size = kSize;
    return ringMap(fishEyeMapField(), {.tolerance = 1e-10}, setup);
}

}  // namespace eikon::accuracy
