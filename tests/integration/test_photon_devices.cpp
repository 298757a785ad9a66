// render.device for the photon pass: the native tracer
// (render/stages/NativePhotonTrace) against the compute shader on the
// default scene (uniform air, the analytic glass sphere, the floor), traced
// by photons. Both compile the same text (shaders/common/photon_tracer.glsl
// and what it includes) and tally in the same fixed-point units, as
// integers, so:
// - run to run, the native pass gives the same tallies bit for bit (its
//   threads' integer sums do not depend on the order they are added in);
// - against the compute shader, a photon's tallies are the same integers
//   wherever its path is the same. What differs is only how each compiler
//   rounds the path (llvmpipe may fuse a product and a sum, and samples the
//   textures with its own lerps): a photon whose rounding carries it across
//   a texel's edge, the sphere's rim or the roulette's threshold moves its
//   power elsewhere. The bound: the photons whose fate differs, and the
//   receiver texels whose tallies differ, are a small fraction (stated
//   below) of those the pass traces, and the emitted power — which no
//   rounding of a path touches — is the same integer. Under llvmpipe (a
//   software rasterizer, as in CI) no photon's path differs: measured, the
//   receiver tallies, every power of the ledger, the counts and the steps
//   are the same integers, and that is asserted there. Only the mean
//   invariant error, a sum of each step's rounding of |v| − n, differs
//   (0.6% on the default scene).
#include "io/scene/SceneParser.h"
#include "tests/integration/GlTestContext.h"
#include "tests/integration/LightPassDevices.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace eikon {
namespace {

using render::StageDevice;

Scene defaultPhotonScene() {
    Scene scene = loadSceneFile(std::string(EIKON_SOURCE_DIR) + "/scenes/default.json");
    scene.tracer.estimator = TracerDesc::Estimator::Photons;
    scene.render.photons = 1 << 18;
    scene.render.errorEstimate = false;
    return scene;
}

std::uint64_t sumOf(const std::vector<std::uint64_t>& values) {
    std::uint64_t sum = 0;
    for (std::uint64_t value : values) sum += value;
    return sum;
}

class PhotonDevices : public ::testing::Test {
protected:
    void SetUp() override { test::glContext(); }
};

TEST_F(PhotonDevices, TheNativePassIsTheSameRunToRun) {
    const test::LightPassOutputs first = test::traceLightPass(defaultPhotonScene(), ComputeDevice::Cpu);
    const test::LightPassOutputs second = test::traceLightPass(defaultPhotonScene(), ComputeDevice::Cpu);
    EXPECT_EQ(first.device, StageDevice::Cpu) << first.deviceReason;
    EXPECT_TRUE(first.deviceReason.empty());
    ASSERT_FALSE(first.tallies.empty());
    EXPECT_GT(sumOf(first.tallies), 0u) << "an unlit floor proves nothing";
    EXPECT_EQ(first.tallies, second.tallies);
    EXPECT_EQ(first.stats.steps, second.stats.steps);
    EXPECT_EQ(first.stats.photonsReceived, second.stats.photonsReceived);
    EXPECT_EQ(first.stats.received.r, second.stats.received.r);
    EXPECT_EQ(first.stats.maxInvariantError, second.stats.maxInvariantError);
    EXPECT_EQ(first.stats.meanInvariantError, second.stats.meanInvariantError);
}

TEST_F(PhotonDevices, TheNativePassAgreesWithTheComputeShader) {
    const test::LightPassOutputs gpu = test::traceLightPass(defaultPhotonScene(), ComputeDevice::Gpu);
    const test::LightPassOutputs cpu = test::traceLightPass(defaultPhotonScene(), ComputeDevice::Cpu);
    EXPECT_EQ(gpu.device, StageDevice::Gpu);
    EXPECT_EQ(cpu.device, StageDevice::Cpu) << cpu.deviceReason;
    ASSERT_EQ(gpu.tallies.size(), cpu.tallies.size());

    const double photons = static_cast<double>(gpu.stats.photons);
    // Emission rounds no path: the same integers.
    EXPECT_EQ(gpu.stats.emitted.r, cpu.stats.emitted.r);
    EXPECT_EQ(gpu.stats.emitted.b, cpu.stats.emitted.b);
    // Every photon ends once on both.
    EXPECT_EQ(cpu.stats.photonsEscaped + cpu.stats.photonsReceived + cpu.stats.photonsCutOff + cpu.stats.photonsBlocked,
              gpu.stats.photons);
    const auto apart = [](std::uint64_t a, std::uint64_t b) { return static_cast<double>(a > b ? a - b : b - a); };
    const double fatesApart = apart(gpu.stats.photonsReceived, cpu.stats.photonsReceived) +
                              apart(gpu.stats.photonsEscaped, cpu.stats.photonsEscaped) +
                              apart(gpu.stats.photonsCutOff, cpu.stats.photonsCutOff) +
                              apart(gpu.stats.photonsBlocked, cpu.stats.photonsBlocked);
    std::size_t texelsDiffering = 0, texelsLit = 0;
    double unitsMoved = 0.0;
    for (std::size_t i = 0; i < gpu.tallies.size(); ++i) {
        texelsLit += gpu.tallies[i] != 0;
        texelsDiffering += gpu.tallies[i] != cpu.tallies[i];
        unitsMoved += apart(gpu.tallies[i], cpu.tallies[i]);
    }
    const double received = static_cast<double>(sumOf(gpu.tallies));
    test::reportFigure("default_photons_fates_apart_per_photon", fatesApart / photons);
    test::reportFigure("default_photons_texels_differing_per_lit", double(texelsDiffering) / double(texelsLit));
    test::reportFigure("default_photons_receiver_units_moved_per_received", unitsMoved / received);
    test::reportFigure("default_photons_steps_ratio", double(cpu.stats.steps) / double(gpu.stats.steps));
    EXPECT_LE(fatesApart, 1e-3 * photons);
    EXPECT_LE(unitsMoved, 1e-2 * received);
    EXPECT_NEAR(double(cpu.stats.steps), double(gpu.stats.steps), 1e-3 * double(gpu.stats.steps));

    if (!test::rendersOnCpu()) return;
    EXPECT_EQ(cpu.tallies, gpu.tallies);
    for (const auto member : {&render::PhotonStats::emitted, &render::PhotonStats::absorbed, &render::PhotonStats::escaped,
                              &render::PhotonStats::received, &render::PhotonStats::cutOff, &render::PhotonStats::blocked,
                              &render::PhotonStats::reflected, &render::PhotonStats::rouletteGain})
        for (int c = 0; c < 3; ++c) EXPECT_EQ((cpu.stats.*member)[c], (gpu.stats.*member)[c]);
    EXPECT_EQ(cpu.stats.photonsReceived, gpu.stats.photonsReceived);
    EXPECT_EQ(cpu.stats.photonsEscaped, gpu.stats.photonsEscaped);
    EXPECT_EQ(cpu.stats.steps, gpu.stats.steps);
    EXPECT_EQ(cpu.stats.surfaceReflections, gpu.stats.surfaceReflections);
    EXPECT_EQ(cpu.stats.surfaceTransmissions, gpu.stats.surfaceTransmissions);
    EXPECT_EQ(cpu.stats.maxInvariantError, gpu.stats.maxInvariantError);
}

TEST_F(PhotonDevices, AScenePastTheNativePassRunsTheComputeShaderAndSaysWhy) {
    Scene scene = defaultPhotonScene();
    scene.tracer.integrator = TracerDesc::Integrator::Rk4;
    scene.render.photons = 1 << 12;
    const test::LightPassOutputs out = test::traceLightPass(scene, ComputeDevice::Cpu);
    EXPECT_EQ(out.device, StageDevice::Gpu);
    EXPECT_NE(out.deviceReason.find("leapfrog"), std::string::npos) << out.deviceReason;
}

}  // namespace
}  // namespace eikon
