// Heat shimmer: rays crossing a rising plume of hot air, against the
// reference tracer.
#include "verify/accuracy/Cases.h"

#include "verify/reference/AnalyticFields.h"
#include "verify/reference/ReferenceTracer.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace eikon::accuracy {

namespace {

// A plume n = 1 − 1e-3·exp(−ρ²/(2s²))·exp(−y/0.5 m), s = 4 cm, about the
// vertical axis of a 0.32 m cube of 64³ voxels; parallel light along +z
// crosses it and is deflected by up to ~1.5 mrad. Error: the angle between
// each exit direction and the reference tracer's, over the largest reference
// deflection (RMS over rays within 2.5 s of the axis).
class HeatShimmerCase final : public AccuracyCase {
public:
    std::string name() const override { return "heat_shimmer"; }
    std::vector<RunSettings> sweep(bool quick) const override { return standardSweep(quick, {}); }
    std::vector<RunRecord> run(const RunSettings& settings, bool quick) const override {
        constexpr double kWidth = 0.04, kHalf = 0.16;
        const reference::HeatPlumeField field(1.0, 1e-3, kWidth, 0.0, 0.5, glm::dvec3(0.0));
        Scene scene;
        scene.grid.boundsMin = glm::dvec3(-kHalf, 0.0, -kHalf);
        scene.grid.boundsMax = glm::dvec3(kHalf, 2 * kHalf, kHalf);
        scene.render.width = 8;
        scene.render.height = 8;
        scene.render.photons = pathCasePhotons(quick);
        LightDesc light;
        light.kind = LightDesc::Kind::Directional;
        light.direction = glm::dvec3(0.0, 0.0, 1.0);
        light.irradiance = Rgb(1.0);
        scene.lights.push_back(light);
        applySettings(scene, settings, glm::ivec3(64));
        const GridSpec grid = scene.grid.spec();
        const double h = grid.voxelSize().x;
        const GpuTrace trace =
            traceOnGpu(scene, sampleIndexField(field, grid, 1.0), pathRequest(scene, 0.5 / h, settings.stepVoxels));

        const reference::ReferenceTracer reference(field, {.tolerance = 1e-13, .maxStep = 2e-3});
        std::vector<double> angles;
        double largest = 0.0;
        for (const PhotonPath& path : trace.paths) {
            if (path.size() < 3 || std::abs(path[0].x) > 2.5 * kWidth || path[0].y < 2 * h ||
                path[0].y > 2 * kHalf - 2 * h)
                continue;
            const reference::ReferenceResult truth =
                reference.trace(reference.start(path[0], {0.0, 0.0, 1.0}), 10.0,
                                [&](const reference::RayState& s) { return s.x.z - kHalf; });
            const glm::dvec3 expected = glm::normalize(truth.state.v);
            const glm::dvec3 direction = glm::normalize(path.back() - path[path.size() - 2]);
            angles.push_back(glm::length(direction - expected));
            largest = std::max(largest, glm::length(expected - glm::dvec3(0.0, 0.0, 1.0)));
        }
        Measurement m{name(), "angle between exit direction and the reference tracer's, over the largest deflection (RMS)",
                      largest > 0.0 ? rms(angles) / largest : 0.0, -1.0, static_cast<int>(angles.size())};
        return {makeRecord(scene, settings, trace, m, 0.24)};
    }
};

}  // namespace

std::unique_ptr<AccuracyCase> makeHeatShimmerCase() { return std::make_unique<HeatShimmerCase>(); }

}  // namespace eikon::accuracy
