#include "verify/accuracy/GlassSphereMap.h"

#include "verify/accuracy/ReceiverCaseScene.h"
#include "verify/accuracy/RingMap.h"
#include "verify/reference/SphereCaustic.h"

#include <cmath>
#include <numbers>

namespace eikon::accuracy {

namespace {

constexpr double kRadius = 0.25, kGlass = 1.5, kHalf = 0.35;  // m; the cube is ±kHalf
constexpr double kWidth = 2.0 * kHalf / 64;                    // the smoothing: one voxel
constexpr double kSize = 0.2;                                  // m: the receiver's edge
constexpr int kTexels = 64;
constexpr int kRings = 20'000;

double focalPlane() { return -glassSphereMapField().paraxialFocusFromCentre(); }

}  // namespace

const reference::GlassSphereField& glassSphereMapField() {
    static const reference::GlassSphereField field(glm::dvec3(0.0), kRadius, kGlass, kWidth);
    return field;
}

Scene glassSphereMapScene() {
    Scene scene = receiverCaseScene(glm::dvec3(-kHalf), glm::dvec3(kHalf), glm::ivec3(64), 1.0);
    scene.lights.push_back(unitBeam(glm::dvec3(0.0, -1.0, 0.0)));
    scene.receivers.push_back(
        unfilteredReceiver(glm::dvec3(0.0, focalPlane(), 0.0), glm::dvec3(0.0, 1.0, 0.0), kSize, kTexels));
    scene.objects.push_back(coverSphere(glm::dvec3(0.0), kRadius + 4.0 * kWidth, 1.0));
    return scene;
}

std::vector<double> glassSphereReferenceMap() {
    // Past 4 widths of smoothing the rays fly straight, landing at ρ = b, off the receiver.
    const double outermost = kRadius + 4.0 * kWidth, db = outermost / kRings;
    const double plane = focalPlane();
    RingMapSetup setup;
    setup.rings = kRings;
    setup.ray = [=](int k) {
        const double b = (k + 0.5) * db;
        return RingRay{glm::dvec3(b, kHalf, 0.0), glm::dvec3(0.0, -1.0, 0.0), 2.0 * std::numbers::pi * b * db};
    };
    setup.plane = [=](const reference::RayState& s) { return s.x.y - plane; };
    setup.radius = [](const glm::dvec3& x) { return std::hypot(x.x, x.z); };
    setup.texels = kTexels;
    setup.size = kSize;
    return ringMap(glassSphereMapField(), {.tolerance = 1e-10, .maxStep = 0.25 * kWidth}, setup);
}

ObjectDesc sharpGlassSphere() {
    ObjectDesc glass;
    glass.kind = ObjectDesc::Kind::Sphere;
    glass.sphere = {glm::dvec3(0.0), kRadius};
    glass.material.index = kGlass;
    glass.surface = ObjectDesc::Surface::Sharp;
    return glass;
}

Scene sharpGlassSphereMapScene(int causticMapTexels) {
    Scene scene = glassSphereMapScene();
    scene.objects = {sharpGlassSphere()};
    scene.render.method = RenderDesc::Method::ImageSpace;
    scene.render.causticMapTexels = causticMapTexels;
    return scene;
}

std::vector<double> sharpGlassSphereReferenceMap() {
    reference::SphereCausticSetup setup;
    setup.centre = glm::dvec3(0.0);
    setup.radius = kRadius;
    setup.sphereIndex = kGlass;
    setup.receiverCentre = glm::dvec3(0.0, focalPlane(), 0.0);
    setup.size = kSize;
    setup.resolution = kTexels;
    return reference::integrateSphereCausticUnderBeam(setup, 1.0).irradiance;
}

}  // namespace eikon::accuracy
