// The ledger's check of what the lights emitted against what they state:
// the stated power (statedEmission, from the lights' statements in double
// precision) agrees with the packets' emitted total for each kind of light
// and domain — a spot wider than the cone toward the traced region, cut by
// it, included — and `eikon run`'s warning says when the two differ.
#include "apps/eikon/PowerWarning.h"
#include "render/stages/PhotonEmission.h"
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <string>

namespace eikon {
namespace {

// A light 1.5 m above a 0.6 m receiver square in a small empty grid: the
// light's domain is the narrow cone (or, for the wavefront, its gnomonic
// square) toward that region, so a wide spot is cut by it.
Scene ledgerScene(LightDesc light, TracerDesc::Estimator estimator) {
    Scene scene = test::emptyScene(glm::dvec3(-0.3, 0.0, -0.3), glm::dvec3(0.3, 0.6, 0.3), 8);
    scene.receivers.push_back(test::floorReceiver(0.0, 0.6, 16));
    scene.lights.push_back(light);
    scene.render.photons = 1 << 16;
    scene.tracer.estimator = estimator;
    return scene;
}

LightDesc spotLight(double coneDeg, double falloffDeg, glm::dvec3 axis) {
    LightDesc spot;
    spot.kind = LightDesc::Kind::Spot;
    spot.position = glm::dvec3(0.05, 1.5, 0.0);
    spot.direction = glm::normalize(axis);
    spot.power = Rgb(1.0, 2.0, 0.5);
    spot.coneAngleDeg = coneDeg;
    spot.falloffDeg = falloffDeg;
    return spot;
}

TEST(EmissionLedger, StatedPowerIsWhatThePacketsCarry) {
    LightDesc point;
    point.position = glm::dvec3(0.05, 1.5, 0.0);
    point.power = Rgb(3.0);
    const LightDesc lights[] = {point, test::directionalLight({0.2, -1.0, 0.1}, 2.0),
                                spotLight(30.0, 0.0, {0.1, -1.0, 0.05}), spotLight(40.0, 25.0, {0.3, -1.0, 0.0}),
                                spotLight(12.0, 0.0, {0.0, -1.0, 0.0})};
    for (const auto estimator : {TracerDesc::Estimator::Photons, TracerDesc::Estimator::Wavefront}) {
        double worst = 0.0;
        for (const LightDesc& light : lights) {
            const Scene scene = ledgerScene(light, estimator);
            const render::PhotonStats stats = test::trace(scene).stats;
            worst = std::max(worst, stats.emissionError());
            EXPECT_LT(stats.emissionError(), 1e-3) << "light " << static_cast<int>(light.kind);
            if (light.kind == LightDesc::Kind::Spot && light.coneAngleDeg > 12.0) {
                EXPECT_LT(stats.stated.g, 0.95 * light.power.g) << "the region cuts the spot's cone";
            }
        }
        test::reportFigure(estimator == TracerDesc::Estimator::Photons ? "ledger_emission_error_photons"
                                                                       : "ledger_emission_error_wavefront",
                           worst);
    }
}

// The stated power does not come from the packets: a spot whose cone lies
// in its domain states its whole power, whatever its angle.
TEST(EmissionLedger, ASpotsWholeConeStatesItsPower) {
    const render::Box region{glm::dvec3(-1.0), glm::dvec3(1.0)};
    for (const double cone : {0.01, 1.0, 60.0}) {
        LightDesc spot = spotLight(cone, 0.0, {0.3, -0.8, 0.52});
        spot.position = glm::dvec3(0.0);
        for (const bool wavefront : {false, true}) {
            const Rgb stated = render::statedEmission({spot}, region, wavefront);
            EXPECT_DOUBLE_EQ(stated.g, 2.0) << cone;
        }
    }
}

render::FrameResult resultOf(Rgb emitted, Rgb stated) {
    render::FrameResult result;
    result.photons.emitted = emitted;
    result.photons.escaped = emitted;
    result.photons.stated = stated;
    return result;
}

TEST(EmissionLedger, WarningSaysWhenTheEmissionIsOff) {
    app::PowerWarning quiet;
    testing::internal::CaptureStderr();
    quiet.check(0, resultOf(Rgb(1.0), Rgb(1.0005)));
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");

    app::PowerWarning warning;
    testing::internal::CaptureStderr();
    warning.check(3, resultOf(Rgb(0.3, 0.3, 0.3), Rgb(1.0, 1.0, 1.0)));
    const std::string said = testing::internal::GetCapturedStderr();
    EXPECT_NE(said.find("frame 3: the lights emitted 0.9 W where they state 3 W"), std::string::npos) << said;
    EXPECT_NE(said.find("emission_error"), std::string::npos) << said;
}

}  // namespace
}  // namespace eikon
