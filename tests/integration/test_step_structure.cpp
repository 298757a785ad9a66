// StepStructureStage over grids that are neither cubes nor powers of two:
// its pyramid holds the grid's own nodes, ⌈r/2^k⌉ along each axis r at level
// k, and no padding; and every voxel's label is the one an octree computed
// here on the host from its definition gives ([Sun08] §4.2: nodes of 2^k
// voxels on a side, each node's δn and κ range over the 3×3×3
// neighbourhoods of its voxels inside the grid; octree_label.comp's rule).
#include "gl/GpuMemory.h"
#include "render/stages/PrepareStage.h"
#include "render/stages/StepStructureStage.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace eikon {
namespace {

struct Range {
    float indexMin = 1e30f, indexMax = -1e30f, kappaMin = 1e30f, kappaMax = -1e30f;
};

// δn 0 and κ 0 but in a few boxes, so that labels range over every level.
FieldSet boxedFields(const glm::ivec3& resolution, bool extinction, std::mt19937& random) {
    FieldSet fields;
    fields.grid = GridSpec{resolution, {0.0, 0.0, 0.0}, {1.3, 0.45, 2.0}};
    fields.deltaIndex.assign(fields.grid.cellCount(), 0.0f);
    if (extinction) fields.extinction.assign(3 * fields.grid.cellCount(), 0.0f);
    std::uniform_real_distribution<float> index(-1e-3f, 1e-3f), kappa(0.0f, 0.05f);
    auto fill = [&](glm::ivec3 from, glm::ivec3 to, bool absorbs) {
        for (int k = from.z; k < std::min(to.z, resolution.z); ++k)
            for (int j = from.y; j < std::min(to.y, resolution.y); ++j)
                for (int i = from.x; i < std::min(to.x, resolution.x); ++i) {
                    const std::size_t cell = fields.grid.linearIndex(i, j, k);
                    fields.deltaIndex[cell] = index(random);
                    if (extinction && absorbs)
                        for (std::size_t c = 0; c < 3; ++c) fields.extinction[3 * cell + c] = kappa(random);
                }
    };
    fill({1, 0, 2}, {3, 2, 4}, false);
    fill({resolution.x - 2, resolution.y - 1, resolution.z - 3}, resolution, true);
    fill({resolution.x / 2, 2, resolution.z / 2}, {resolution.x / 2 + 1, 3, resolution.z / 2 + 2}, true);
    fields.indexVersion = fields.extinctionVersion = 1;
    return fields;
}

// Level 0's range at a voxel: its 3×3×3 neighbourhood, clamped to the grid.
Range voxelRange(const FieldSet& fields, glm::ivec3 voxel) {
    const glm::ivec3 r = fields.grid.resolution;
    Range range;
    for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const glm::ivec3 c = glm::clamp(voxel + glm::ivec3(dx, dy, dz), glm::ivec3(0), r - 1);
                const std::size_t cell = fields.grid.linearIndex(c.x, c.y, c.z);
                const float index = fields.deltaIndex[cell];
                float kappa = 0.0f;
                if (!fields.extinction.empty())
                    kappa = std::max({fields.extinction[3 * cell], fields.extinction[3 * cell + 1],
                                      fields.extinction[3 * cell + 2]});
                range.indexMin = std::min(range.indexMin, index);
                range.indexMax = std::max(range.indexMax, index);
                range.kappaMin = std::min(range.kappaMin, kappa);
                range.kappaMax = std::max(range.kappaMax, kappa);
            }
    return range;
}

// The node of `level` (2^level voxels on a side) at `node`: its voxels inside the grid.
Range nodeRange(const FieldSet& fields, glm::ivec3 node, int level) {
    const glm::ivec3 r = fields.grid.resolution;
    const glm::ivec3 from = node * (1 << level), to = glm::min(from + (1 << level), r);
    Range range;
    for (int k = from.z; k < to.z; ++k)
        for (int j = from.y; j < to.y; ++j)
            for (int i = from.x; i < to.x; ++i) {
                const Range v = voxelRange(fields, {i, j, k});
                range.indexMin = std::min(range.indexMin, v.indexMin);
                range.indexMax = std::max(range.indexMax, v.indexMax);
                range.kappaMin = std::min(range.kappaMin, v.kappaMin);
                range.kappaMax = std::max(range.kappaMax, v.kappaMax);
            }
    return range;
}

std::vector<float> stepTexels(const gl::Texture3D& texture, const GridSpec& grid) {
    std::vector<float> values(4 * grid.cellCount());
    glGetTextureImage(texture.id(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(values.size() * sizeof(float)),
                      values.data());
    return values;
}

class StepStructure : public ::testing::Test {
protected:
    void SetUp() override { test::glContext(); }
};

// Level 0 at the origin, levels k ≥ 1 beside it along x, stacked along z
// (common/octree_levels.glsl): the texture is the grid and half of it again,
// not a cube of 256³ (55 times the grid's cells).
TEST_F(StepStructure, PyramidHoldsTheGridsOwnNodes) {
    const glm::ivec3 r{16, 96, 200};  // hot_road_mirage's former grid
    const std::uint64_t before = gl::gpuBytesHeld();
    const GridSpec grid{r, {0.0, 0.0, 0.0}, {16.0, 3.0, 600.0}};
    render::StepStructureStage stage(grid, TracerDesc{}, false, false);
    EXPECT_EQ(stage.levels(), 9);  // 2^8 = 256 ≥ 200 cells: one node spans the grid
    std::uint64_t stacked = 0;  // the levels k ≥ 1 along z
    glm::ivec3 size = r;
    for (int level = 1; level < stage.levels(); ++level) {
        size = (size + 1) / 2;
        stacked += std::uint64_t(size.z);
    }
    EXPECT_EQ(size, glm::ivec3(1));
    const std::uint64_t texels = std::uint64_t(r.x + (r.x + 1) / 2) * std::uint64_t(r.y) *
                                 std::max<std::uint64_t>(std::uint64_t(r.z), stacked);
    const std::uint64_t cells = grid.cellCount();
    EXPECT_EQ(gl::gpuBytesHeld() - before, 16 * texels + 16 * cells);  // RGBA32F pyramid and step sizes
    test::reportFigure("pyramid_texels_over_cells", double(texels) / double(cells));
    test::reportFigure("padded_cube_texels_over_cells", 256.0 * 256.0 * 256.0 / double(cells));
}

void expectLabelsOfDefinition(const glm::ivec3& resolution, bool extinction) {
    std::mt19937 random(17);
    const FieldSet fields = boxedFields(resolution, extinction, random);
    TracerDesc tracer;
    tracer.epsilonPrime = 0.2;  // some capped nodes as well
    render::FieldTextures textures;
    textures.upload(render::hostUpload(fields));
    render::StepStructureStage stage(fields.grid, tracer, extinction, false);
    stage.run(textures.index(), textures);  // no smoothing: the raw δn
    const std::vector<float> texels = stepTexels(stage.stepTexture(), fields.grid);

    const int levels = stage.levels();
    const Range whole = nodeRange(fields, glm::ivec3(0), levels - 1);
    const float fieldRange = 1.0f * (whole.indexMax - whole.indexMin);
    const glm::dvec3 h = fields.grid.voxelSize();
    const auto nodeEdge = static_cast<float>(std::max({h.x, h.y, h.z}) * std::sqrt(3.0));
    const auto minStep = static_cast<float>(tracer.stepVoxels * fields.grid.smallestVoxelEdge());
    const auto cappedStep = static_cast<float>(tracer.maxStepVoxels * fields.grid.smallestVoxelEdge());
    std::vector<int> perLevel(static_cast<std::size_t>(levels), 0);
    int mismatches = 0;
    for (int k = 0; k < resolution.z; ++k)
        for (int j = 0; j < resolution.y; ++j)
            for (int i = 0; i < resolution.x; ++i) {
                glm::vec3 label{0.0f, minStep, 0.0f};
                for (int level = levels - 1; level >= 0; --level) {
                    const Range range = nodeRange(fields, glm::ivec3(i, j, k) >> level, level);
                    if ((range.kappaMax - range.kappaMin) * nodeEdge * std::exp2(float(level)) >=
                        float(render::kOpticalDepthTolerance))
                        continue;
                    const float variation = range.indexMax - range.indexMin;
                    const float empty = range.kappaMax <= 0.0f ? 1.0f : 0.0f;
                    if (variation <= float(tracer.epsilon) * fieldRange) {
                        label = {float(level), 1e30f, empty};
                        break;
                    }
                    if (variation <= float(tracer.epsilonPrime) * fieldRange) {
                        label = {float(level), cappedStep, empty};
                        break;
                    }
                }
                const float* texel = &texels[4 * fields.grid.linearIndex(i, j, k)];
                if (glm::vec3(texel[0], texel[1], texel[2]) != label && ++mismatches <= 5)
                    ADD_FAILURE() << "voxel (" << i << ", " << j << ", " << k << "): (" << texel[0] << ", " << texel[1]
                                  << ", " << texel[2] << "), by definition (" << label.x << ", " << label.y << ", "
                                  << label.z << ")";
                ++perLevel[static_cast<std::size_t>(label.x)];
            }
    EXPECT_EQ(mismatches, 0);
    int levelsUsed = 0;
    for (int count : perLevel) levelsUsed += count > 0;
    EXPECT_GE(levelsUsed, 3) << "a test of labels that are all alike";
}

TEST_F(StepStructure, LabelsAreThoseOfTheOctreeOverOddSides) {
    expectLabelsOfDefinition({13, 6, 22}, false);
    expectLabelsOfDefinition({9, 17, 5}, true);
}

// What FrameRenderer writes in place of prepare and step_structure for a
// uniform medium (render/graph/UniformMedium.h) against what they compute:
// the labels exactly; the gradient exactly for δn = 0 and to float rounding
// of the smoothing's weights (Σw = 1 to a few ulp) otherwise.
void expectClosedFormOfUniformMedium(float deltaIndex, float kappa) {
    FieldSet fields;
    fields.grid = GridSpec{{11, 7, 20}, {0.0, 0.0, 0.0}, {1.1, 0.5, 2.0}};
    fields.deltaIndex.assign(fields.grid.cellCount(), deltaIndex);
    if (kappa > 0.0f) fields.extinction.assign(3 * fields.grid.cellCount(), kappa);
    fields.indexVersion = fields.extinctionVersion = 1;
    GridDesc desc;
    desc.resolution = fields.grid.resolution;
    desc.boundsMin = fields.grid.boundsMin;
    desc.boundsMax = fields.grid.boundsMax;
    render::FieldTextures textures;
    textures.upload(render::hostUpload(fields));
    render::PrepareStage prepare(desc, textures);  // σ = 1.5 voxels
    render::StepStructureStage steps(fields.grid, TracerDesc{}, kappa > 0.0f, false);
    steps.enableReference(0.01);

    prepare.run(textures);
    steps.run(prepare.smoothedIndex(textures), textures);
    const std::vector<float> gradient = stepTexels(textures.gradient(), fields.grid);
    const std::vector<float> labels = stepTexels(steps.stepTexture(), fields.grid);
    const std::vector<float> reference = stepTexels(steps.referenceStepTexture(), fields.grid);

    prepare.fillUniform(textures, deltaIndex);
    steps.fillUniform(kappa <= 0.0f);
    EXPECT_EQ(stepTexels(steps.stepTexture(), fields.grid), labels);
    EXPECT_EQ(stepTexels(steps.referenceStepTexture(), fields.grid), reference);
    const std::vector<float> filled = stepTexels(textures.gradient(), fields.grid);
    double worst = 0.0;
    for (std::size_t i = 0; i < filled.size(); ++i) worst = std::max(worst, double(std::abs(filled[i] - gradient[i])));
    EXPECT_LE(worst, 4e-7 * std::abs(deltaIndex) / fields.grid.smallestVoxelEdge()) << "δn " << deltaIndex;
    EXPECT_EQ(labels[0], float(steps.levels() - 1));  // one node spans the grid
}

TEST_F(StepStructure, AUniformMediumHasTheClosedFormOfEveryStage) {
    expectClosedFormOfUniformMedium(0.0f, 0.0f);
    expectClosedFormOfUniformMedium(2.5e-4f, 0.0f);
    expectClosedFormOfUniformMedium(0.0f, 0.3f);
}

}  // namespace
}  // namespace eikon
