// A light pass shared among processes (render/stages/LightPassShare.h), with
// the processes played in turn by one: K shares whose raw tallies are summed
// must give, bit for bit, the receiver map, the statistics and the recorded
// photon paths of the whole pass — for photons (uneven photon ranges, paths
// recorded across share boundaries) and for wavefronts (seed chunks). The
// fluence of a scattering medium sums floats and agrees to rounding.
#include "io/scene/SceneParser.h"
#include "render/graph/FrameRenderer.h"
#include "sim/voxelize/AnalyticVoxelizer.h"
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

namespace eikon {
namespace {

// Adds the tallies of shares K−1 … 1 (traced first) into those of share 0.
struct SharedSums {
    render::LightPassTallies total;
    bool empty = true;
    void add(const render::LightPassTallies& tallies) {
        if (empty) {
            total = tallies;
            empty = false;
            return;
        }
        ASSERT_EQ(total.sums.size(), tallies.sums.size());
        ASSERT_EQ(total.floatSums.size(), tallies.floatSums.size());
        for (std::size_t i = 0; i < total.sums.size(); ++i) total.sums[i] += tallies.sums[i];
        for (std::size_t i = 0; i < total.maxima.size(); ++i)
            total.maxima[i] = std::max(total.maxima[i], tallies.maxima[i]);
        for (std::size_t i = 0; i < total.floatSums.size(); ++i) total.floatSums[i] += tallies.floatSums[i];
    }
};

class InTurnExchange final : public render::LightPassExchange {
public:
    InTurnExchange(SharedSums& sums, bool writesFrame) : sums_(sums), writesFrame_(writesFrame) {}
    void combine(render::LightPassTallies& tallies) override {
        sums_.add(tallies);
        if (writesFrame_) tallies = sums_.total;
        ++calls;
    }
    bool receivesTotals() const override { return writesFrame_; }
    int calls = 0;

private:
    SharedSums& sums_;
    bool writesFrame_;
};

render::RendererOptions recordingOptions() {
    render::RendererOptions options;
    options.photons.recordPathVertices = 8;
    options.photons.recordedPhotons = 32;
    options.photons.recordStride = 97;  // recorded photons fall in every share
    options.drawsImage = false;
    return options;
}

// The pass traced as `shares` shares, share 0 last; what share 0 holds.
test::TraceResult traceShared(const Scene& scene, const FieldSet& fields, unsigned shares) {
    SharedSums sums;
    test::TraceResult first;
    for (unsigned index = shares; index-- > 0;) {
        InTurnExchange exchange(sums, index == 0);
        render::RendererOptions options = recordingOptions();
        options.share = {index, shares};
        options.exchange = &exchange;
        test::TraceResult result = test::traceFields(scene, fields, options);
        EXPECT_EQ(exchange.calls, 1) << "one exchange a pass";
        if (index == 0) first = std::move(result);
    }
    return first;
}

void expectSameStatistics(const render::PhotonStats& whole, const render::PhotonStats& shared) {
    for (const auto& [a, b] : {std::pair{whole.emitted, shared.emitted}, {whole.absorbed, shared.absorbed},
                               {whole.escaped, shared.escaped}, {whole.received, shared.received},
                               {whole.cutOff, shared.cutOff}, {whole.blocked, shared.blocked},
                               {whole.reflected, shared.reflected}, {whole.rouletteGain, shared.rouletteGain},
                               {whole.unfollowed, shared.unfollowed}})
        for (int c = 0; c < 3; ++c) EXPECT_EQ(a[c], b[c]);
    EXPECT_EQ(whole.photonsEscaped, shared.photonsEscaped);
    EXPECT_EQ(whole.photonsReceived, shared.photonsReceived);
    EXPECT_EQ(whole.photonsCutOff, shared.photonsCutOff);
    EXPECT_EQ(whole.photonsBlocked, shared.photonsBlocked);
    EXPECT_EQ(whole.steps, shared.steps);
    EXPECT_EQ(whole.voxelDeposits, shared.voxelDeposits);
    EXPECT_EQ(whole.surfaceReflections, shared.surfaceReflections);
    EXPECT_EQ(whole.surfaceTransmissions, shared.surfaceTransmissions);
    EXPECT_EQ(whole.maxInvariantError, shared.maxInvariantError);
    EXPECT_EQ(whole.meanInvariantError, shared.meanInvariantError);
    EXPECT_EQ(whole.photonsResumed, shared.photonsResumed);
    EXPECT_EQ(whole.wavefront.patches, shared.wavefront.patches);
    EXPECT_EQ(whole.wavefront.splits, shared.wavefront.splits);
    EXPECT_EQ(whole.wavefront.atLimit, shared.wavefront.atLimit);
    EXPECT_EQ(whole.wavefront.rays, shared.wavefront.rays);
}

Scene reducedDefaultScene(const std::string& estimator) {
    return loadSceneFile(std::string(EIKON_SOURCE_DIR) + "/scenes/default.json",
                         {"grid.resolution=[48,40,48]", "render.photons=100003", "receivers.0.resolution=96",
                          "tracer.estimator=\"" + estimator + "\"", "tracer.wavefront.grid_cells=24"});
}

TEST(SharedLightPass, ThreeSharesOfPhotonsGiveTheWholePassBitForBit) {
    test::glContext();
    const Scene scene = reducedDefaultScene("photons");
    const FieldSet fields = sim::voxelizeScene(scene);
    const test::TraceResult whole = test::traceFields(scene, fields, recordingOptions());
    const test::TraceResult shared = traceShared(scene, fields, 3);
    ASSERT_GT(whole.stats.photonsReceived, 30000u) << "the floor is lit";
    EXPECT_GT(whole.stats.surfaceTransmissions, 5000u) << "photons go through the sphere";
    EXPECT_EQ(whole.map, shared.map) << "the receiver map, bit for bit";
    expectSameStatistics(whole.stats, shared.stats);
    int recorded = 0;
    for (const glm::vec4& vertex : whole.paths) recorded += vertex.w == 1.0f;
    EXPECT_GT(recorded, 32) << "paths were recorded";
    EXPECT_EQ(whole.paths, shared.paths);
    EXPECT_EQ(whole.pathPower, shared.pathPower);
}

TEST(SharedLightPass, TwoSharesOfWavefrontSeedsGiveTheWholePassBitForBit) {
    test::glContext();
    const Scene scene = reducedDefaultScene("wavefront");
    const FieldSet fields = sim::voxelizeScene(scene);
    render::RendererOptions options;
    options.drawsImage = false;
    const test::TraceResult whole = test::traceFields(scene, fields, options);
    SharedSums sums;
    test::TraceResult shared;
    for (unsigned index = 2; index-- > 0;) {
        InTurnExchange exchange(sums, index == 0);
        render::RendererOptions share = options;
        share.share = {index, 2};
        share.exchange = &exchange;
        test::TraceResult result = test::traceFields(scene, fields, share);
        if (index == 1) {
            EXPECT_LT(result.stats.wavefront.patches, whole.stats.wavefront.patches) << "a part only";
        }
        if (index == 0) shared = std::move(result);
    }
    ASSERT_GT(whole.stats.wavefront.splits, 100u) << "the wavefront refined";
    EXPECT_EQ(whole.map, shared.map) << "the receiver map, bit for bit";
    expectSameStatistics(whole.stats, shared.stats);
}

// A scattering slab: the fluence sums floats, so shares agree to rounding.
TEST(SharedLightPass, TheFluenceOfAScatteringMediumAgreesToRounding) {
    test::glContext();
    Scene scene = reducedDefaultScene("photons");
    scene.medium.extinction = Rgb(0.5);
    scene.medium.scattering = Rgb(0.5);
    const FieldSet fields = sim::voxelizeScene(scene);
    ASSERT_TRUE(fields.hasScattering());
    const test::TraceResult whole = test::traceFields(scene, fields, recordingOptions());
    const test::TraceResult shared = traceShared(scene, fields, 2);
    EXPECT_EQ(whole.map, shared.map);
    ASSERT_EQ(whole.fluence.size(), shared.fluence.size());
    double sum = 0.0, difference = 0.0;
    for (std::size_t i = 0; i < whole.fluence.size(); ++i) {
        sum += std::abs(whole.fluence[i]);
        difference += std::abs(whole.fluence[i] - shared.fluence[i]);
    }
    ASSERT_GT(sum, 0.0);
    EXPECT_LT(difference / sum, 1e-5) << "relative L1 of the fluence";
}

}  // namespace
}  // namespace eikon
