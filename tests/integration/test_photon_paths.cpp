// Recorded photon paths for export: every k-th photon's vertices with the
// power it carries there. In a uniform absorbing medium the power at each
// vertex must be the emitted power times exp(−κ·L), L the path length
// marched inside the grid so far (Beer–Lambert, per channel).
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>

namespace eikon::test {
namespace {

bool insideBox(const glm::dvec3& x, const glm::dvec3& lo, const glm::dvec3& hi) {
    return x.x >= lo.x && x.y >= lo.y && x.z >= lo.z && x.x <= hi.x && x.y <= hi.y && x.z <= hi.z;
}

TEST(PhotonPaths, PowerAlongRecordedPathsFollowsBeerLambert) {
    const glm::dvec3 lo(-0.5), hi(0.5);
    Scene scene = emptyScene(lo, hi, 16);
    scene.medium.extinction = Rgb(0.5, 1.0, 2.0);
    scene.lights.push_back(directionalLight({0.2, -1.0, 0.1}, 1.0));
    scene.receivers.push_back(floorReceiver(-0.45, 0.9, 16));  // the light aims at it, through the medium
    scene.render.photons = 4096;
    scene.tracer.stepPolicy = TracerDesc::StepPolicy::Uniform;  // half-voxel steps: many vertices per path
    // A prime stride: photon i takes stratum (i mod s, i / s) of its emitter's
    // s × s grid, so a stride sharing a factor with s would record one column.
    const int recorded = 32, perPhoton = 128, stride = 127;
    const TraceResult result = trace(scene, {.recordPathVertices = perPhoton, .recordedPhotons = recorded,
                                             .recordStride = stride});
    ASSERT_EQ(result.paths.size(), static_cast<std::size_t>(recorded * perPhoton));
    ASSERT_EQ(result.pathPower.size(), result.paths.size());

    // All photons of one light carry the same power: the emitted total over the count.
    const glm::dvec3 perPhotonPower = result.stats.emitted / static_cast<double>(result.stats.photons);
    int paths = 0, checkedVertices = 0;
    double worst = 0.0, spreadX = 0.0, meanX = 0.0;
    for (int photon = 0; photon < recorded; ++photon) {
        const std::size_t first = static_cast<std::size_t>(photon * perPhoton);
        if (result.paths[first].w != 1.0f) continue;
        ++paths;
        meanX += result.paths[first + 2].x;
        double inside = 0.0;  // path length marched in the grid so far
        for (int v = 0; v < perPhoton && result.paths[first + static_cast<std::size_t>(v)].w == 1.0f; ++v) {
            const std::size_t k = first + static_cast<std::size_t>(v);
            if (v > 0) {
                const glm::dvec3 a(result.paths[k - 1]), b(result.paths[k]);
                // A marching step starts inside the grid (and is attenuated whole);
                // flights to and from the grid start outside.
                if (insideBox(a, lo, hi)) inside += glm::length(b - a);
            }
            for (int c = 0; c < 3; ++c) {
                const double expected = perPhotonPower[c] * std::exp(-scene.medium.extinction[c] * inside);
                worst = std::max(worst, std::abs(result.pathPower[k][c] / expected - 1.0));
            }
            ++checkedVertices;
        }
    }
    EXPECT_EQ(paths, recorded);
    EXPECT_GT(checkedVertices, recorded * 8);  // some photons cross only a corner of the grid
    // float32 power, one exp per step: relative 1e-4.
    test::reportFigure("path_power_beer_lambert_max_relative_error", worst);
    test::reportFigure("path_power_vertices_checked", checkedVertices);
    EXPECT_LT(worst, 1e-4);
    // The photons recorded are spread over the light's disk, not one stratum:
    // their entry points span a good part of the 1 m grid.
    meanX /= paths;
    for (int photon = 0; photon < recorded; ++photon)
        spreadX = std::max(spreadX, std::abs(result.paths[static_cast<std::size_t>(photon * perPhoton) + 2].x - meanX));
    EXPECT_GT(spreadX, 0.25);
}

// Photons that miss a small receiver leave the grid: each path ends where
// its photon crossed the grid's boundary (the last step's overshoot moved
// back onto the box), so an exported path never reaches far from the scene.
TEST(PhotonPaths, EscapingPathsEndOnTheGridsBoundary) {
    const glm::dvec3 lo(-0.5), hi(0.5);
    Scene scene = emptyScene(lo, hi, 16);
    scene.lights.push_back(directionalLight({0.2, -1.0, 0.1}, 1.0));
    scene.receivers.push_back(floorReceiver(-0.45, 0.3, 16));
    scene.render.photons = 4096;
    scene.tracer.stepPolicy = TracerDesc::StepPolicy::Uniform;
    const int recorded = 64, perPhoton = 128;
    const TraceResult result = trace(scene, {.recordPathVertices = perPhoton, .recordedPhotons = recorded,
                                             .recordStride = 61});
    const double tolerance = 1e-4;
    int escaped = 0;
    for (int photon = 0; photon < recorded; ++photon) {
        const std::size_t first = static_cast<std::size_t>(photon * perPhoton);
        int last = -1;
        for (int v = 0; v < perPhoton && result.paths[first + static_cast<std::size_t>(v)].w == 1.0f; ++v) last = v;
        ASSERT_GE(last, 1) << "photon " << photon << " was recorded entering the grid";
        for (int v = 1; v <= last; ++v) {  // vertex 0 is on the light's beam, above the grid
            const glm::dvec3 x(result.paths[first + static_cast<std::size_t>(v)]);
            EXPECT_TRUE(insideBox(x, lo - tolerance, hi + tolerance)) << "photon " << photon << " vertex " << v;
        }
        const glm::dvec3 end(result.paths[first + static_cast<std::size_t>(last)]);
        const bool onReceiver = std::abs(end.y + 0.45) < tolerance;
        if (onReceiver) continue;
        const glm::dvec3 toFace = glm::min(end - lo, hi - end);
        EXPECT_LT(std::min(toFace.x, std::min(toFace.y, toFace.z)), tolerance) << "photon " << photon << " ends on a face";
        ++escaped;
    }
    EXPECT_GT(escaped, recorded / 4) << "many photons miss the small receiver";
}

}  // namespace
}  // namespace eikon::test
