// A spot light emits its stated power at every cone angle, on and off the
// axes of the grid, with both light-pass estimators: the power measured is
// the ledger's emitted total, summed on the device from the photons or
// wavefront patches that actually left the light (and, by the balance every
// trace checks, what escaped). The light sits in the middle of an empty
// grid, so the region toward which light is sent is the whole sphere and the
// spot's whole cone is emitted.
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <string>

namespace eikon {
namespace {

Scene spotScene(double coneDeg, double falloffDeg, glm::dvec3 axis, TracerDesc::Estimator estimator) {
    Scene scene = test::emptyScene(glm::dvec3(-0.5), glm::dvec3(0.5), 8);
    LightDesc spot;
    spot.kind = LightDesc::Kind::Spot;
    spot.position = glm::dvec3(0.0);
    spot.direction = glm::normalize(axis);
    spot.power = Rgb(1.0, 2.0, 0.5);
    spot.coneAngleDeg = coneDeg;
    spot.falloffDeg = falloffDeg;
    scene.lights.push_back(spot);
    scene.render.photons = 1 << 16;
    scene.tracer.estimator = estimator;
    return scene;
}

// Worst relative error of the emitted power over the channels.
double emittedError(const Scene& scene) {
    const render::PhotonStats stats = test::trace(scene).stats;
    const Rgb& stated = scene.lights[0].power;
    return std::max({std::abs(stats.emitted.r / stated.r - 1.0), std::abs(stats.emitted.g / stated.g - 1.0),
                     std::abs(stats.emitted.b / stated.b - 1.0)});
}

void checkSpotPower(TracerDesc::Estimator estimator, const std::string& name) {
    const glm::dvec3 axes[] = {{0.0, -1.0, 0.0}, {0.3, -0.8, 0.52}};
    double worst = 0.0;
    for (const double cone : {0.01, 0.05, 0.5, 1.0, 10.0, 30.0, 60.0, 90.0})
        for (int a = 0; a < 2; ++a)
            for (const double falloff : {0.0, 0.5 * cone}) {
                const double error = emittedError(spotScene(cone, falloff, axes[a], estimator));
                worst = std::max(worst, error);
                EXPECT_LT(error, 1e-3) << name << ": cone " << cone << "°, falloff " << falloff << "°, "
                                       << (a == 0 ? "on axis" : "oblique");
            }
    test::reportFigure(("spot_emitted_worst_relative_error_" + name).c_str(), worst);
}

TEST(SpotPower, PhotonsEmitTheStatedPower) { checkSpotPower(TracerDesc::Estimator::Photons, "photons"); }

TEST(SpotPower, WavefrontEmitsTheStatedPower) { checkSpotPower(TracerDesc::Estimator::Wavefront, "wavefront"); }

}  // namespace
}  // namespace eikon
