// render.device: the grid passes' native loops (render/stages/NativePrepare,
// NativeStepStructure) against their compute shaders, on the same fields.
// Both compile the same kernel text (shaders/common/index_smoothing.glsl,
// index_gradient.glsl, octree_ranges.glsl, octree_labels.glsl), so what
// may differ is only how each compiler rounds it: the GLSL compiler may fuse
// a product and a sum (GLSL allows it without `precise`), C++ here does not.
//
// The bounds, from the kernels' arithmetic (u = 2⁻²⁴, the unit roundoff):
// - smoothed δn: each of the three passes sums radius + 1 weighted terms
//   with weights that sum to one, so a fused multiply–add moves each
//   partial sum by at most u·max|δn|: |Δ| ≤ 3·(radius + 1)·u·max|δn|;
// - gradient: a difference of two smoothed values over span·h, so
//   |Δ∇n| ≤ 2·(that bound)/(span·h) + 2u·|∇n| (the division's own rounding);
// - pyramid and labels from the same smoothed δn: min, max and the label's
//   comparisons round nothing but the products of the rule, computed alike:
//   equal, bit for bit.
#include "io/scene/SceneParser.h"
#include "render/graph/FrameRenderer.h"
#include "render/stages/GaussianKernel.h"
#include "render/stages/PrepareStage.h"
#include "render/stages/StepStructureStage.h"
#include "sim/SceneFields.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace eikon {
namespace {

using render::StageDevice;

constexpr double kUnitRoundoff = 0x1p-24;

std::vector<float> texels(const gl::Texture3D& texture, const GridSpec& grid, GLenum format, int channels) {
    std::vector<float> values(static_cast<std::size_t>(channels) * grid.cellCount());
    render::downloadTexels(texture, format, values.data(), values.size() * sizeof(float));
    return values;
}

struct GridPassOutputs {
    std::vector<float> smoothed, gradient, labels, reference;
};

// Prepare, then the step structure with its reference labels, on `device`.
// With `smoothedFrom`, the step structure reads that stage's smoothed δn in
// place of its own prepare's (the same input on both devices).
GridPassOutputs runGridPasses(const GridDesc& desc, const FieldSet& fields, StageDevice device,
                              const render::PrepareStage* smoothedFrom = nullptr,
                              const render::FieldTextures* smoothedTextures = nullptr) {
    render::FieldTextures textures;
    textures.upload(render::hostUpload(fields));
    TracerDesc tracer;
    tracer.epsilonPrime = 0.05;  // the capped tier as well
    render::PrepareStage prepare(desc, textures, device);
    render::StepStructureStage steps(fields.grid, tracer, !fields.extinction.empty(), !fields.emission.empty(), device);
    steps.enableReference(0.5 * fields.grid.smallestVoxelEdge());
    prepare.run(textures);
    const gl::Texture3D& smoothed =
        smoothedFrom ? smoothedFrom->smoothedIndex(*smoothedTextures) : prepare.smoothedIndex(textures);
    steps.run(smoothed, textures);
    glFinish();
    return {texels(prepare.smoothedIndex(textures), fields.grid, GL_RED, 1),
            texels(textures.gradient(), fields.grid, GL_RGBA, 4), texels(steps.stepTexture(), fields.grid, GL_RGBA, 4),
            texels(steps.referenceStepTexture(), fields.grid, GL_RGBA, 4)};
}

int countDifferent(const std::vector<float>& a, const std::vector<float>& b) {
    int different = 0;
    for (std::size_t i = 0; i < a.size(); ++i) different += a[i] != b[i];
    return different;
}

// Both devices on `fields`: the smoothed δn and gradient within the bounds
// above, the labels equal; the step structure once more on one smoothed δn.
void expectSameOnBothDevices(const GridDesc& desc, const FieldSet& fields, const std::string& name) {
    SCOPED_TRACE(name);
    const GridPassOutputs gpu = runGridPasses(desc, fields, StageDevice::Gpu);
    const GridPassOutputs cpu = runGridPasses(desc, fields, StageDevice::Cpu);

    const int radius = static_cast<int>(render::gaussianHalfKernel(desc.smoothingSigmaVoxels, desc.smoothingWindowVoxels).size()) - 1;
    float largest = 0.0f;
    for (float value : fields.deltaIndex) largest = std::max(largest, std::abs(value));
    const double smoothedBound = 3.0 * (radius + 1) * kUnitRoundoff * largest;
    double worstSmoothed = 0.0;
    for (std::size_t i = 0; i < gpu.smoothed.size(); ++i)
        worstSmoothed = std::max(worstSmoothed, double(std::abs(gpu.smoothed[i] - cpu.smoothed[i])));
    EXPECT_LE(worstSmoothed, smoothedBound);

    const glm::dvec3 h = fields.grid.voxelSize();
    double worstGradient = 0.0;  // as a fraction of its bound
    for (std::size_t cell = 0; cell < gpu.smoothed.size(); ++cell)
        for (int axis = 0; axis < 3; ++axis) {
            const std::size_t at = 4 * cell + static_cast<std::size_t>(axis);
            const double bound = 2.0 * smoothedBound / h[axis] + 2.0 * kUnitRoundoff * std::abs(gpu.gradient[at]);
            const double difference = std::abs(gpu.gradient[at] - cpu.gradient[at]);
            worstGradient = std::max(worstGradient, bound > 0.0 ? difference / bound : difference > 0.0 ? 1e30 : 0.0);
        }
    EXPECT_LE(worstGradient, 1.0);
    EXPECT_EQ(countDifferent(gpu.smoothed, cpu.smoothed) == 0, countDifferent(gpu.gradient, cpu.gradient) == 0)
        << "the gradient differs only where the smoothing does";

    // The step structure from one smoothed δn: bit for bit.
    render::FieldTextures shared;
    shared.upload(render::hostUpload(fields));
    render::PrepareStage gpuPrepare(desc, shared, StageDevice::Gpu);
    gpuPrepare.run(shared);
    const GridPassOutputs fromOne = runGridPasses(desc, fields, StageDevice::Cpu, &gpuPrepare, &shared);
    EXPECT_EQ(countDifferent(fromOne.labels, gpu.labels), 0);
    EXPECT_EQ(countDifferent(fromOne.reference, gpu.reference), 0);
    // And through each device's own smoothing, as a frame runs them.
    const int labelsDiffering = countDifferent(cpu.labels, gpu.labels);
    EXPECT_EQ(labelsDiffering, 0);

    int levelsUsed = 0;  // a test of labels that are all alike would prove little
    for (int level = 0; level < 16; ++level)
        for (std::size_t cell = 0; cell < gpu.smoothed.size(); ++cell)
            if (gpu.labels[4 * cell] == float(level)) {
                ++levelsUsed;
                break;
            }
    EXPECT_GE(levelsUsed, 3);
    test::reportFigure((name + "_smoothed_worst_over_unit_roundoff_of_max").c_str(),
                       worstSmoothed / (kUnitRoundoff * largest));
    test::reportFigure((name + "_gradient_worst_over_bound").c_str(), worstGradient);
    test::reportFigure((name + "_smoothed_cells_differing").c_str(), countDifferent(gpu.smoothed, cpu.smoothed));
    test::reportFigure((name + "_labels_differing").c_str(), labelsDiffering);
}

class GridPassDevices : public ::testing::Test {
protected:
    void SetUp() override { test::glContext(); }
};

// A graded 128³ field: two Gaussian bumps of hot air (δn ~ −1e-4) beside a
// glass-like interface (δn 0 → 0.5 over two voxels), κ graded in a slab and
// a small glowing box, so that every branch of the kernels runs.
FieldSet gradedField(const glm::ivec3& r) {
    FieldSet fields;
    fields.grid = GridSpec{r, {-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}};
    fields.deltaIndex.resize(fields.grid.cellCount());
    fields.extinction.assign(3 * fields.grid.cellCount(), 0.0f);
    fields.emission.assign(3 * fields.grid.cellCount(), 0.0f);
    for (int k = 0; k < r.z; ++k)
        for (int j = 0; j < r.y; ++j)
            for (int i = 0; i < r.x; ++i) {
                const glm::dvec3 x = fields.grid.cellCentre(i, j, k);
                const std::size_t cell = fields.grid.linearIndex(i, j, k);
                const glm::dvec3 a = x - glm::dvec3(-0.2, 0.1, 0.0), b = x - glm::dvec3(0.15, -0.2, 0.1);
                double delta = -1.2e-4 * std::exp(-glm::dot(a, a) / 0.01) - 0.7e-4 * std::exp(-glm::dot(b, b) / 0.003);
                if (x.z > 0.3) delta += 0.25 * (1.0 + std::tanh((x.x - 0.3) / (2.0 * fields.grid.voxelSize().x)));
                fields.deltaIndex[cell] = static_cast<float>(delta);
                if (x.y < -0.3)
                    for (std::size_t c = 0; c < 3; ++c)
                        fields.extinction[3 * cell + c] = static_cast<float>((0.5 + c) * (-0.3 - x.y));
                if (glm::all(glm::lessThan(glm::abs(x - glm::dvec3(0.0, 0.3, -0.3)), glm::dvec3(0.03))))
                    fields.emission[3 * cell] = 1.0f;
            }
    fields.indexVersion = fields.extinctionVersion = 1;
    return fields;
}

TEST_F(GridPassDevices, AGraded128CubeGivesTheSameGradientAndLabels) {
    GridDesc desc;  // σ = 1.5 voxels, the 9³ window
    desc.resolution = {128, 128, 128};
    expectSameOnBothDevices(desc, gradedField(desc.resolution), "graded_128");
}

TEST_F(GridPassDevices, OddSidesAndAWideKernel) {
    GridDesc desc;
    desc.resolution = {13, 6, 22};
    desc.smoothingSigmaVoxels = 3.0;  // radius 9: wider than the grid's y side
    expectSameOnBothDevices(desc, gradedField(desc.resolution), "odd_sides");
}

// heat_shimmer's own field: its solver's hot sheets over the grill after
// ten frames, through the octree as well (the scene itself steps uniformly).
TEST_F(GridPassDevices, HeatShimmersFieldGivesTheSameGradientAndLabels) {
    Scene scene = loadSceneFile(std::string(EIKON_SOURCE_DIR) + "/scenes/heat_shimmer.json");
    sim::SceneFields fields(scene);
    for (int frame = 0; frame < 10; ++frame) fields.advanceFrame();
    expectSameOnBothDevices(scene.grid, fields.fields(), "heat_shimmer");
}

// The frame a renderer draws on each device: heat_shimmer's field as the
// plain view sees it (the scene's BOS camera replaced by a view down the
// grill onto a checkerboard floor 1 m below, 8° below the horizon) at
// 160×120, the same to the bounds above carried through the camera rays —
// measured here as the largest difference of linear radiance.
TEST_F(GridPassDevices, HeatShimmersFrameIsTheSameOnBothDevices) {
    Scene scene = loadSceneFile(std::string(EIKON_SOURCE_DIR) + "/scenes/heat_shimmer.json");
    scene.diagnostic.reset();
    scene.camera.position = glm::dvec3(0.0, 0.57, 3.0);
    scene.camera.target = glm::dvec3(0.0, 0.02, -0.8);
    scene.camera.fovDeg = 1.2;
    scene.render.environment.kind = EnvironmentDesc::Kind::Sky;
    scene.render.environment.groundHeight = -1.0;
    scene.render.environment.checkerSize = 0.03;
    scene.render.samplesPerPixel = 1;
    scene.render.writeHdr = true;  // the linear image compared below
    scene.render.width = 160;
    scene.render.height = 120;
    scene.render.errorEstimate = false;
    sim::SceneFields fields(scene);
    for (int frame = 0; frame < 10; ++frame) fields.advanceFrame();
    std::vector<float> images[2];
    for (const StageDevice device : {StageDevice::Gpu, StageDevice::Cpu}) {
        scene.render.device = device == StageDevice::Cpu ? ComputeDevice::Cpu : ComputeDevice::Gpu;
        render::FrameRenderer renderer(scene, fields.fields());
        const render::FrameResult frame = renderer.render(fields.fields());
        const auto prepare = std::find_if(frame.stages.begin(), frame.stages.end(),
                                          [](const render::StageReport& stage) { return stage.name == "prepare"; });
        ASSERT_NE(prepare, frame.stages.end());
        EXPECT_TRUE(prepare->ran);
        EXPECT_EQ(prepare->device, device);
        images[device == StageDevice::Cpu] = frame.hdr;
    }
    ASSERT_FALSE(images[0].empty());
    ASSERT_EQ(images[0].size(), images[1].size());
    double brightest = 0.0, worst = 0.0;
    for (std::size_t i = 0; i < images[0].size(); ++i) {
        brightest = std::max(brightest, double(images[0][i]));
        worst = std::max(worst, double(std::abs(images[0][i] - images[1][i])));
    }
    EXPECT_GT(brightest, 0.0) << "a black frame proves nothing";
    test::reportFigure("heat_shimmer_frame_worst_difference_over_brightest", worst / brightest);
    EXPECT_LE(worst, 1e-5 * brightest);
}

}  // namespace
}  // namespace eikon
