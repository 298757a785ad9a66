// Inside the varying box a diagnostic's leapfrog steps across octree nodes
// where the medium is nearly uniform (render/stages/DiagnosticNodeSteps.h).
// The levels: a node is nearly uniform only with every voxel that reaches
// into it (the smoothing's, the gradient's and the filter's reach) within
// ε of the field's range and κ the same. The march: against uniform steps
// through a bump that varies everywhere (so that the box is the whole grid)
// but nearly not at all far from its centre, the maps move by far less than
// the closed-form tests' limits (docs/accuracy.md, "Diagnostics").
#include "render/stages/DiagnosticNodeSteps.h"
#include "render/stages/DiagnosticStage.h"
#include "render/stages/PrepareStage.h"
#include "tests/integration/GaussianBump.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

namespace eikon {
namespace {

using namespace test;

// 12 × 12 × 12 bricks of δn 1e-6, one brick (3, 3, 3) holding a voxel at 1e-4.
render::BrickRanges oneVaryingBrick() {
    render::BrickRanges bricks;
    bricks.count = glm::ivec3(12);
    bricks.lowest.assign(12 * 12 * 12, glm::vec4(1e-6f, 0.0f, 0.0f, 0.0f));
    bricks.highest = bricks.lowest;
    bricks.highest[bricks.index({3, 3, 3})].x = 1e-4f;
    return bricks;
}

TEST(DiagnosticNodeSteps, ANodeIsNearlyUniformOnlyWithAllThatReachesIntoIt) {
    const render::BrickRanges bricks = oneVaryingBrick();
    // A reach of 3.5 voxels: a node's neighbouring bricks (4 voxels) bring theirs in.
    const std::vector<float> levels = render::nearlyUniformNodeLevels(bricks, 3.5, 0.002);
    const auto level = [&](int i, int j, int k) { return levels[bricks.index({i, j, k})]; };
    EXPECT_EQ(level(3, 3, 3), 0.0f);  // the varying brick
    EXPECT_EQ(level(4, 4, 4), 0.0f);  // its neighbour, within its reach
    EXPECT_EQ(level(5, 5, 5), 2.0f);  // clear alone; its 8-voxel node (4–5)³ reaches brick 3
    EXPECT_EQ(level(0, 0, 0), 3.0f);  // the 8-voxel node (0–1)³ is clear; the 16-voxel (0–3)³ holds brick 3
    EXPECT_EQ(level(6, 6, 6), 3.0f);  // the 16-voxel node (4–7)³ reaches brick 3
    EXPECT_EQ(level(8, 8, 8), 5.0f);  // the 32-voxel node (8–15)³ reaches bricks 7–11 only; the 64-voxel one holds 3
    // Without the reach the neighbour would be taken for uniform, its 16-voxel node whole.
    EXPECT_EQ(render::nearlyUniformNodeLevels(bricks, 0.0, 0.002)[bricks.index({4, 4, 4})], 4.0f);
    // ε is a fraction of the field's range: 1e-4 − 1e-6 here.
    render::BrickRanges slight = bricks;
    slight.highest[slight.index({10, 10, 10})].x = 1e-6f + 0.0019f * (1e-4f - 1e-6f);
    EXPECT_EQ(render::nearlyUniformNodeLevels(slight, 3.5, 0.002)[slight.index({10, 10, 10})], 5.0f);
    slight.highest[slight.index({10, 10, 10})].x = 1e-6f + 0.0021f * (1e-4f - 1e-6f);
    EXPECT_EQ(render::nearlyUniformNodeLevels(slight, 3.5, 0.002)[slight.index({10, 10, 10})], 0.0f);
    // Any change of κ within a node counts.
    render::BrickRanges absorbing = bricks;
    absorbing.highest[absorbing.index({10, 10, 10})].z = 1e-9f;
    EXPECT_EQ(render::nearlyUniformNodeLevels(absorbing, 3.5, 0.002)[absorbing.index({10, 10, 10})], 0.0f);
}

TEST(DiagnosticNodeSteps, SteppingAcrossNearlyUniformNodesMovesTheMapsFarLessThanTheClosedFormLimits) {
    glContext();
    DiagnosticDesc knifeEdge;
    knifeEdge.type = DiagnosticDesc::Type::Schlieren;
    DiagnosticDesc bos;
    bos.type = DiagnosticDesc::Type::Bos;
    Bump bump;
    bump.centre = {0.05, -0.03, 0.02};
    for (const DiagnosticDesc& diagnostic : {DiagnosticDesc{}, knifeEdge, bos}) {
        Scene scene = bumpScene(64, 48, diagnostic);
        if (diagnostic.type == DiagnosticDesc::Type::Bos) scene.camera.projection = CameraDesc::Projection::Perspective;
        const FieldSet fields = sampledBump(scene, bump);
        render::FieldTextures textures;
        textures.upload(render::hostUpload(fields));
        render::PrepareStage prepare(scene.grid, textures);
        prepare.run(textures);
        const render::VaryingVoxels varying = render::varyingVoxels(render::hostUpload(fields));
        ASSERT_EQ(varying.box.lowest, glm::ivec3(0)) << "the bump must vary everywhere for the box to be the grid";
        const std::vector<float> levels = render::nearlyUniformNodeLevels(varying.bricks, 3.5, scene.tracer.epsilon);
        const auto nodeBricks = std::count_if(levels.begin(), levels.end(), [](float level) { return level > 0.0f; });
        ASSERT_GT(nodeBricks, static_cast<long>(levels.size() / 4)) << "the test needs nodes to step across";
        render::DiagnosticStage uniform(scene, textures), stepped(scene, textures);
        stepped.setVaryingVoxels(varying);
        uniform.run(textures);
        stepped.run(textures);
        const std::string name = std::to_string(static_cast<int>(diagnostic.type));
        const std::vector<glm::vec4> uniformRays = uniform.downloadRays(), steppedRays = stepped.downloadRays();
        double deflectionChange = 0.0, opdChange = 0.0;
        for (std::size_t i = 0; i < uniformRays.size(); ++i) {
            deflectionChange = std::max({deflectionChange, std::abs(double(uniformRays[i].x) - steppedRays[i].x),
                                         std::abs(double(uniformRays[i].y) - steppedRays[i].y)});
            opdChange = std::max(opdChange, std::abs(double(uniformRays[i].z) - steppedRays[i].z));
            EXPECT_EQ(uniformRays[i].w, steppedRays[i].w) << name << " ray " << i;
        }
        std::cout << name << " nodes in " << nodeBricks << " of " << levels.size() << " bricks; deflection change "
                  << deflectionChange / bump.peakDeflection() << ", OPD " << opdChange / bump.peakOpd()
                  << " of their peaks\n";
        EXPECT_LE(deflectionChange, 1e-3 * bump.peakDeflection()) << name;
        EXPECT_LE(opdChange, 1e-3 * bump.peakOpd()) << name;
    }
}

}  // namespace
}  // namespace eikon
