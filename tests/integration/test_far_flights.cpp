// Light outside the field grid flies straight however far it goes: the same
// scene — a point light above a glass ball in the grid and a receiver below
// the grid, both outside it — scaled by 1e-6 and 1e6 (every position and
// length; the light's power kept, so the irradiance scales as 1/s²) gives the
// same received fraction of the emitted power and the same map shape as at
// scale 1, with both light-pass estimators. A flight that ended at a fixed
// distance (once 10 km) lost all the light of the scene at 1e6.
#include "io/scene/SceneParser.h"
#include "render/graph/FrameRenderer.h"
#include "sim/voxelize/AnalyticVoxelizer.h"
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

namespace eikon {
namespace {

// The scene at scale s, written as a scene file would be, so that the
// parser's ranges are part of what is checked; estimator "image_space": the
// image-space method instead of the eikonal tracer.
Scene scaledScene(double s, const std::string& estimator) {
    auto at = [s](double x, double y, double z) { return nlohmann::json::array({s * x, s * y, s * z}); };
    nlohmann::json document = {
        {"grid", {{"resolution", {32, 32, 32}}, {"bounds", {{"min", at(-0.6, 0.0, -0.6)}, {"max", at(0.6, 1.0, 0.6)}}}}},
        {"medium", {{"index", 1.0}}},
        {"objects", {{{"type", "sphere"}, {"center", at(0.0, 0.55, 0.0)}, {"radius", 0.25 * s}, {"index", 1.5}}}},
        {"lights", {{{"type", "point"}, {"position", at(0.1, 3.0, 0.0)}, {"power", {30.0, 30.0, 30.0}}}}},
        {"receivers",
         {{{"type", "plane"}, {"point", at(0.0, -2.0, 0.0)}, {"normal", {0, 1, 0}}, {"size", 3.0 * s}, {"resolution", 32}}}},
        {"render", {{"photons", 1 << 16}, {"width", 8}, {"height", 8}, {"seed", 1}}},
        {"tracer", {{"estimator", estimator}}}};
    if (estimator == "image_space") {
        document.erase("tracer");
        document["render"] = {{"method", "image_space"}, {"width", 8}, {"height", 8}, {"caustic_map_texels", 64}};
    }
    return parseScene(document, "far_flights.json");
}

struct Reach {
    double receivedFraction = 0.0;
    std::vector<double> shape;  // the map over its sum
};

Reach reach(double s, const std::string& estimator) {
    const test::TraceResult result = test::trace(scaledScene(s, estimator));
    Reach r;
    r.receivedFraction = result.stats.received.g / result.stats.emitted.g;
    double sum = 0.0;
    for (std::size_t i = 1; i < result.map.size(); i += 3) sum += result.map[i];
    for (std::size_t i = 1; i < result.map.size(); i += 3) r.shape.push_back(sum > 0.0 ? result.map[i] / sum : 0.0);
    return r;
}

double shapeDifference(const Reach& a, const Reach& b) {
    double difference = 0.0;
    for (std::size_t i = 0; i < a.shape.size(); ++i) difference += std::abs(a.shape[i] - b.shape[i]);
    return difference;
}

TEST(FarFlights, ScaledScenesReceiveTheSameLight) {
    for (const std::string estimator : {"photons", "wavefront"}) {
        const Reach unit = reach(1.0, estimator);
        ASSERT_GT(unit.receivedFraction, 0.1) << estimator;
        for (const double s : {1e-6, 1e6}) {
            const Reach scaled = reach(s, estimator);
            const std::string name = estimator + (s < 1.0 ? "_1e-6" : "_1e6");
            test::reportFigure(("far_flights_received_fraction_change_" + name).c_str(),
                               scaled.receivedFraction / unit.receivedFraction - 1.0);
            test::reportFigure(("far_flights_map_l1_" + name).c_str(), shapeDifference(scaled, unit));
            EXPECT_NEAR(scaled.receivedFraction / unit.receivedFraction, 1.0, 1e-3) << name;
            EXPECT_LT(shapeDifference(scaled, unit), 0.01) << name;
        }
    }
}

// Image space draws the surfaces from the light and the camera between
// planes set by the scene's extent (once fixed at 1 mm and 1 km), and steps
// off surfaces by lengths of the scene's scale (once fixed, 1e-6 to 1e-4 m):
// scaled by 1e-6 and 1e6 its receiver map has the same shape.
TEST(FarFlights, ImageSpaceScaledScenesReceiveTheSameLight) {
    test::glContext();
    auto shape = [](double s) {
        const Scene scene = scaledScene(s, "image_space");
        const FieldSet fields = sim::voxelizeScene(scene);
        render::FrameRenderer renderer(scene, fields, {.photons = {}});
        renderer.render(fields);
        const std::vector<float> map = renderer.receivers().download(0);
        Reach r;
        double sum = 0.0;
        for (std::size_t i = 1; i < map.size(); i += 3) sum += map[i];
        for (std::size_t i = 1; i < map.size(); i += 3) r.shape.push_back(sum > 0.0 ? map[i] / sum : 0.0);
        return r;
    };
    const Reach unit = shape(1.0);
    for (const double s : {1e-6, 1e6}) {
        const Reach scaled = shape(s);
        test::reportFigure(s < 1.0 ? "far_flights_map_l1_image_space_1e-6" : "far_flights_map_l1_image_space_1e6",
                           shapeDifference(scaled, unit));
        EXPECT_LT(shapeDifference(scaled, unit), 0.01) << s;
    }
}

}  // namespace
}  // namespace eikon
