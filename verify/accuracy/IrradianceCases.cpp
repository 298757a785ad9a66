// Irradiance cases in clear and absorbing media: the inverse-square law of a
// point light on a plane and Beer–Lambert attenuation through a slab.
#include "verify/accuracy/CaseScenes.h"
#include "verify/accuracy/Cases.h"
#include "verify/reference/ReceiverFilter.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace eikon::accuracy {

namespace {

// Point light of intensity I = 1 W/sr, 1 m above the centre of a 1 m square
// receiver (64² texels), in clear air on a 16³ grid. Truth: E = I·h/d³
// averaged over each texel (8² samples) and, for photons, passed through the
// receiver's 3×3 filter (the wavefront has none); error: RMS over texels of
// the relative difference.
class PointLightCase final : public AccuracyCase {
public:
    std::string name() const override { return "point_light"; }
    std::vector<RunSettings> sweep(bool quick) const override {
        return standardSweep(quick, {.steps = false, .octree = false, .grid = false, .photons = true, .wavefront = true});
    }
    std::vector<RunRecord> run(const RunSettings& settings, bool) const override {
        constexpr int kTexels = 64;
        constexpr double kHeight = 1.0, kSize = 1.0;
        Scene scene = boxScene(glm::dvec3(-0.5, 0.0, -0.5), glm::dvec3(0.5, 1.1, 0.5));
        LightDesc light;
        light.position = glm::dvec3(0.0, kHeight, 0.0);
        light.power = Rgb(4.0 * std::numbers::pi);  // I = 1 W/sr
        scene.lights.push_back(light);
        scene.receivers.push_back(floorReceiver(0.0, kSize, kTexels));
        scene.render.photons = 1 << 16;
        applySettings(scene, settings, glm::ivec3(16));
        FieldSet fields;
        fields.grid = scene.grid.spec();
        fields.deltaIndex.assign(fields.grid.cellCount(), 0.0f);
        fields.indexVersion = 1;
        const GpuTrace trace = traceOnGpu(scene, fields);

        std::vector<double> truth(kTexels * kTexels);
        const double texel = kSize / kTexels;
        for (int j = 0; j < kTexels; ++j)
            for (int i = 0; i < kTexels; ++i) {
                double sum = 0.0;
                for (int b = 0; b < 8; ++b)
                    for (int a = 0; a < 8; ++a) {
                        const double u = -0.5 * kSize + (i + (a + 0.5) / 8) * texel;
                        const double v = -0.5 * kSize + (j + (b + 0.5) / 8) * texel;
                        sum += kHeight / std::pow(u * u + v * v + kHeight * kHeight, 1.5);
                    }
                truth[static_cast<std::size_t>(j * kTexels + i)] = sum / 64.0;
            }
        if (settings.estimator == TracerDesc::Estimator::Photons) truth = reference::binomialFilter(truth, kTexels);
        std::vector<double> relative;
        for (std::size_t t = 0; t < truth.size(); ++t) relative.push_back(trace.receiverMap[3 * t] / truth[t] - 1.0);
        Measurement m{name(), "RMS over texels of the relative irradiance error against E = I*h/d^3",
                      rms(relative), -1.0, static_cast<int>(relative.size())};
        return {makeRecord(scene, settings, trace, m)};
    }
};

// A vertical beam E0 = 1 W/m² through an absorbing slab, κ = (1, 3, 5)/m,
// 0.375 m thick, its faces off the voxel lattice (extinction voxelized as
// each cell's covered fraction); a receiver below it. Truth: E0·exp(−κL);
// error: worst channel's relative error of the mean irradiance.
class BeerLambertCase final : public AccuracyCase {
public:
    std::string name() const override { return "beer_lambert"; }
    std::vector<RunSettings> sweep(bool quick) const override {
        return standardSweep(quick, {.integrators = false, .octree = true, .grid = true, .wavefront = true});
    }
    std::vector<RunRecord> run(const RunSettings& settings, bool) const override {
        constexpr double kTop = 0.675, kBottom = 0.3;
        const Rgb kappa(1.0, 3.0, 5.0);
        Scene scene = boxScene(glm::dvec3(-0.25, 0.0, -0.25), glm::dvec3(0.25, 1.0, 0.25));
        LightDesc light;
        light.kind = LightDesc::Kind::Directional;
        light.direction = glm::dvec3(0.0, -1.0, 0.0);
        light.irradiance = Rgb(1.0);
        scene.lights.push_back(light);
        scene.receivers.push_back(floorReceiver(0.05, 0.3, 8));
        // The slab as a scene object too: photons are emitted toward the objects and receivers.
        ObjectDesc slab;
        slab.kind = ObjectDesc::Kind::Box;
        slab.box = {glm::dvec3(-0.25, kBottom, -0.25), glm::dvec3(0.25, kTop, 0.25)};
        slab.material.extinction = kappa;
        scene.objects.push_back(slab);
        scene.render.photons = 1 << 16;
        applySettings(scene, settings, glm::ivec3(16, 32, 16));
        FieldSet fields;
        fields.grid = scene.grid.spec();
        fields.deltaIndex.assign(fields.grid.cellCount(), 0.0f);
        fields.extinction.assign(3 * fields.grid.cellCount(), 0.0f);
        const double h = fields.grid.voxelSize().y;
        for (int k = 0; k < fields.grid.resolution.z; ++k)
            for (int j = 0; j < fields.grid.resolution.y; ++j)
                for (int i = 0; i < fields.grid.resolution.x; ++i) {
                    const double y0 = j * h, y1 = (j + 1) * h;
                    const double covered = std::max(0.0, std::min(y1, kTop) - std::max(y0, kBottom)) / h;
                    for (int c = 0; c < 3; ++c)
                        fields.extinction[3 * fields.grid.linearIndex(i, j, k) + c] =
                            static_cast<float>(covered * kappa[c]);
                }
        fields.indexVersion = fields.extinctionVersion = 1;
        const GpuTrace trace = traceOnGpu(scene, fields);
        double worst = 0.0;
        const std::size_t texels = trace.receiverMap.size() / 3;
        for (int c = 0; c < 3; ++c) {
            double mean = 0.0;
            for (std::size_t t = 0; t < texels; ++t) mean += trace.receiverMap[3 * t + static_cast<std::size_t>(c)];
            mean /= static_cast<double>(texels);
            worst = std::max(worst, std::abs(mean / std::exp(-kappa[c] * (kTop - kBottom)) - 1.0));
        }
        Measurement m{name(), "worst channel's relative error of the transmitted irradiance against E0*exp(-kL)",
                      worst, -1.0, static_cast<int>(texels)};
        return {makeRecord(scene, settings, trace, m)};
    }
};

}  // namespace

std::unique_ptr<AccuracyCase> makePointLightCase() { return std::make_unique<PointLightCase>(); }
std::unique_ptr<AccuracyCase> makeBeerLambertCase() { return std::make_unique<BeerLambertCase>(); }

}  // namespace eikon::accuracy
