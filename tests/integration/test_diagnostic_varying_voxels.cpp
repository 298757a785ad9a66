// A diagnostic marches only the box where the medium varies
// (render/stages/VaryingVoxels.h) and crosses the rest straight, gathering
// the uniform δn there. Against the march of the whole grid the picture,
// the deflection and where the rays end must not change, and the OPD only
// by float rounding, for a Gaussian bump cut off at 1.5σ, off the axis
// (most rays miss the box, the rest enter it late and leave it early), in
// air whose δn is not 0, with and without smoothing.
#include "bridge/grid/FieldSet.h"
#include "render/stages/DiagnosticStage.h"
#include "render/stages/PrepareStage.h"
#include "render/stages/VaryingVoxels.h"
#include "tests/integration/GaussianBump.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace eikon {
namespace {

using namespace test;

constexpr double kUniformDelta = 3e-6;  // the air's δn outside the bump

FieldSet cutBump(const Scene& scene, const Bump& bump) {
    FieldSet fields;
    fields.grid = scene.grid.spec();
    fields.deltaIndex.resize(fields.grid.cellCount());
    for (int k = 0; k < kBumpCells; ++k)
        for (int j = 0; j < kBumpCells; ++j)
            for (int i = 0; i < kBumpCells; ++i) {
                const glm::dvec3 x = fields.grid.cellCentre(i, j, k);
                const bool inside = glm::length(x - bump.centre) < 1.5 * kBumpSigma;
                fields.deltaIndex[fields.grid.linearIndex(i, j, k)] =
                    static_cast<float>(kUniformDelta + (inside ? bump.deltaIndex(x) : 0.0));
            }
    fields.indexVersion = 1;
    return fields;
}

TEST(DiagnosticVaryingVoxels, MarchingOnlyTheVaryingBoxChangesTheOpdByRoundingAlone) {
    glContext();
    DiagnosticDesc knifeEdge;
    knifeEdge.type = DiagnosticDesc::Type::Schlieren;
    DiagnosticDesc shadowgraph;
    shadowgraph.type = DiagnosticDesc::Type::Shadowgraph;
    shadowgraph.screenDistance = 20.0;
    DiagnosticDesc bos;
    bos.type = DiagnosticDesc::Type::Bos;
    Bump bump;
    bump.centre = {0.12, -0.08, 0.1};
    for (const double smoothing : {0.0, 1.0})
        for (const DiagnosticDesc& diagnostic : {DiagnosticDesc{}, knifeEdge, shadowgraph, bos}) {
            Scene scene = bumpScene(64, 48, diagnostic);
            scene.grid.smoothingSigmaVoxels = smoothing;
            if (diagnostic.type == DiagnosticDesc::Type::Bos) scene.camera.projection = CameraDesc::Projection::Perspective;
            const FieldSet fields = cutBump(scene, bump);
            render::FieldTextures textures;
            textures.upload(render::hostUpload(fields));
            render::PrepareStage prepare(scene.grid, textures);
            prepare.run(textures);
            const render::VaryingVoxels varying = render::varyingVoxels(render::hostUpload(fields));
            ASSERT_FALSE(varying.box.empty());
            ASSERT_GT(varying.box.lowest.x, 8) << "the box must leave most of the grid out for the test to test it";
            render::DiagnosticStage whole(scene, textures), boxed(scene, textures);
            boxed.setVaryingVoxels(varying);
            whole.run(textures);
            boxed.run(textures);
            const std::string name = std::to_string(static_cast<int>(diagnostic.type)) + " σ " + std::to_string(smoothing);
            const std::vector<float> wholeHdr = whole.downloadHdr(), boxedHdr = boxed.downloadHdr();
            float hdrChange = 0.0f;
            for (std::size_t i = 0; i < wholeHdr.size(); ++i)
                hdrChange = std::max(hdrChange, std::abs(wholeHdr[i] - boxedHdr[i]));
            // The fringes turn the OPD's rounding into I/I₀ at π/λ per metre of OPD:
            // a change 40 times below an 8-bit picture's step.
            EXPECT_LE(hdrChange, diagnostic.type == DiagnosticDesc::Type::Interferometry ? 1e-4f : 1e-5f) << name;
            const std::vector<glm::vec4> wholeRays = whole.downloadRays(), boxedRays = boxed.downloadRays();
            const double peakOpd = bump.peakOpd() + kUniformDelta;
            double deflectionChange = 0.0, opdChange = 0.0;
            std::size_t endsChanged = 0;
            for (std::size_t i = 0; i < wholeRays.size(); ++i) {
                deflectionChange = std::max({deflectionChange, std::abs(double(wholeRays[i].x) - boxedRays[i].x),
                                             std::abs(double(wholeRays[i].y) - boxedRays[i].y)});
                opdChange = std::max(opdChange, std::abs(double(wholeRays[i].z) - boxedRays[i].z));
                endsChanged += wholeRays[i].w != boxedRays[i].w ? 1 : 0;
            }
            EXPECT_LE(deflectionChange, 1e-5 * bump.peakDeflection()) << name;
            EXPECT_LE(opdChange, 1e-5 * peakOpd) << name;
            EXPECT_EQ(endsChanged, 0u) << name;
        }
}

}  // namespace
}  // namespace eikon
