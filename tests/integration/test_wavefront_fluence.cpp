// The wavefront's fluence in the grid (tracer.estimator "wavefront" where
// the scene stores fluence or scatters light): each finished patch carries
// its power along its tube's axis by quadratic B-spline weights, so a cell
// holds the fluence averaged over that spline about its centre. Against
// closed forms of that average: a collimated beam through an absorbing
// medium, and a point light's e^{−κr}/r²; the lattice's source, what the
// tubes scattered; and relights that give the same bits.
#include "render/graph/FrameRenderer.h"
#include "sim/voxelize/AnalyticVoxelizer.h"
#include "tests/integration/GlTestContext.h"
#include "tests/integration/TraceHelpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace eikon {
namespace {

using test::emptyScene;

Scene byWavefront(Scene scene) {
    scene.tracer.estimator = TracerDesc::Estimator::Wavefront;
    return scene;
}

// The mean of e^{κs} over the quadratic B-spline of cell width h about
// s = 0, the deposit's weight along one axis: the spline is three boxes of
// width h convolved, so the mean is (sinh(κh/2)/(κh/2))³.
double splineMeanOfExponential(double kappa, double h) {
    const double x = 0.5 * kappa * h;
    return x < 1e-6 ? 1.0 : std::pow(std::sinh(x) / x, 3);
}

// The quadratic B-spline of unit cell width at s.
double spline(double s) {
    s = std::abs(s);
    return s < 0.5 ? 0.75 - s * s : s < 1.5 ? 0.5 * (1.5 - s) * (1.5 - s) : 0.0;
}

// A collimated beam of 3 W/m² straight down through a medium of
// κ = (1, 2, 4) /m (the photons' FluenceFollowsBeerLambert scene): every
// cell off the grid's faces holds E0·e^{−κd} at its centre's depth d times
// the spline's mean, within 0.1% (photons, 2^18 of them, reach 2% averaged over
// 144 cells of a layer).
TEST(WavefrontFluence, BeamFollowsBeerLambertInEveryCell) {
    Scene scene = emptyScene(glm::dvec3(-0.25, 0.0, -0.25), glm::dvec3(0.25, 0.5, 0.25), 20);
    scene.grid.resolution = glm::ivec3(20, 40, 20);
    scene.medium.extinction = Rgb(1.0, 2.0, 4.0);
    scene.tracer.storeFluence = true;
    scene.lights.push_back(test::directionalLight({0.0, -1.0, 0.0}, 3.0));
    const test::TraceResult result = test::trace(byWavefront(scene));
    ASSERT_FALSE(result.fluence.empty());
    EXPECT_GT(result.stats.wavefront.tubes, 0u);
    EXPECT_EQ(result.stats.wavefront.atLimit, 0u);

    const GridSpec grid = scene.grid.spec();
    const double h = grid.voxelSize().y;
    double worst = 0.0;
    glm::ivec4 where(0);
    for (int j = 1; j < 39; ++j)
        for (int k = 1; k < 19; ++k)
            for (int i = 1; i < 19; ++i) {
                const double depth = 0.5 - grid.cellCentre(i, j, k).y;
                for (int c = 0; c < 3; ++c) {
                    const double kappa = scene.medium.extinction[c];
                    const double expected = 3.0 * std::exp(-kappa * depth) * splineMeanOfExponential(kappa, h);
                    const double error = result.fluence[3 * grid.linearIndex(i, j, k) + c] / expected - 1.0;
                    if (std::abs(error) > worst) {
                        worst = std::abs(error);
                        where = glm::ivec4(i, j, k, c);
                    }
                }
            }
    test::reportFigure("wavefront_fluence_beer_lambert_worst_cell_relative_error", worst);
    EXPECT_LT(worst, 1e-3) << "cell " << where.x << ", " << where.y << ", " << where.z << " channel " << where.w;
}

// A point light of power P = 4π W (I = 1 W/sr) at the centre of a 32³ grid
// in a medium of κ = 2 /m: φ = I·e^{−κr}/r², averaged over each cell's
// spline (a 15³ midpoint rule of its product weights), in every cell four
// or more voxels from the light and one from the faces: RMS over the cells
// within 0.05%, the worst cell within 0.5% (0.24%, where the six faces of
// the light's emission domain meet at the cube's corners and the gnomonic
// lattice of patches is sheared, so its tubes sample the spline less evenly).
TEST(WavefrontFluence, PointLightFollowsTheInverseSquareLawInEveryCell) {
    Scene scene = emptyScene(glm::dvec3(-0.5), glm::dvec3(0.5), 32);
    scene.medium.extinction = Rgb(2.0);
    scene.tracer.storeFluence = true;
    LightDesc light;
    light.position = glm::dvec3(0.0);
    light.power = Rgb(4.0 * std::numbers::pi);
    scene.lights.push_back(light);
    const test::TraceResult result = test::trace(byWavefront(scene));
    ASSERT_FALSE(result.fluence.empty());
    EXPECT_GT(result.stats.wavefront.splits, 0u);  // the tubes were split to split_voxels at the grid's faces

    const GridSpec grid = scene.grid.spec();
    const double h = grid.voxelSize().x;
    constexpr int kSamples = 15;
    double worst = 0.0;
    double squared = 0.0;
    int cells = 0;
    glm::ivec3 where(0);
    for (int k = 1; k < 31; ++k)
        for (int j = 1; j < 31; ++j)
            for (int i = 1; i < 31; ++i) {
                const glm::dvec3 centre = grid.cellCentre(i, j, k);
                if (glm::length(centre) < 4.0 * h) continue;
                double expected = 0.0, weights = 0.0;
                for (int c = 0; c < kSamples; ++c)
                    for (int b = 0; b < kSamples; ++b)
                        for (int a = 0; a < kSamples; ++a) {
                            const glm::dvec3 s = ((glm::dvec3(a, b, c) + 0.5) / double(kSamples) - 0.5) * 3.0;
                            const double weight = spline(s.x) * spline(s.y) * spline(s.z);
                            const double r = glm::length(centre + h * s);
                            expected += weight * std::exp(-2.0 * r) / (r * r);
                            weights += weight;
                        }
                expected /= weights;
                const double error = result.fluence[3 * grid.linearIndex(i, j, k) + 1] / expected - 1.0;
                if (std::abs(error) > worst) {
                    worst = std::abs(error);
                    where = glm::ivec3(i, j, k);
                }
                squared += error * error;
                ++cells;
            }
    test::reportFigure("wavefront_fluence_point_light_worst_cell_relative_error", worst);
    test::reportFigure("wavefront_fluence_point_light_rms_cell_relative_error", std::sqrt(squared / cells));
    EXPECT_LT(std::sqrt(squared / cells), 5e-4);
    EXPECT_LT(worst, 5e-3) << "cell " << where.x << ", " << where.y << ", " << where.z;
}

// A scattering sphere (σs/κ = 0.9) lit straight down: the power the tubes
// scatter, the lattice's source, is 0.9 of what the corners' ledger says the
// wavefront lost to extinction, within 0.5% — the tube's axis and the mean of
// its corners are two quadratures of one patch — and a relight gives the
// receiver and fluence bits again (both are fixed-point sums, whatever order
// the tubes finish in).
TEST(WavefrontFluence, TubesFeedTheLatticeAndRelightTheSame) {
    Scene scene = emptyScene(glm::dvec3(-0.25), glm::dvec3(0.25), 32);
    ObjectDesc sphere;
    sphere.kind = ObjectDesc::Kind::Sphere;
    sphere.sphere = {glm::dvec3(0.0), 0.15};
    sphere.material.index = 1.0;
    sphere.material.extinction = Rgb(20.0);
    sphere.material.scattering = Rgb(18.0);
    scene.objects.push_back(sphere);
    scene.lights.push_back(test::directionalLight({0.0, -1.0, 0.0}, 1.0));
    scene.receivers.push_back(test::floorReceiver(-0.24, 0.48, 24));
    scene.tracer.multipleScattering = TracerDesc::MultipleScattering::Lbm;
    scene = byWavefront(scene);
    test::glContext();
    const FieldSet fields = sim::voxelizeScene(scene);
    render::FrameRenderer renderer(scene, fields);
    const render::FrameResult frame = renderer.render(fields);
    ASSERT_TRUE(frame.lattice.has_value());
    for (int c = 0; c < 3; ++c) {
        const double ratio = frame.lattice->channels[c].source / (0.9 * frame.photons.absorbed[c]);
        test::reportFigure(("wavefront_lattice_source_over_scattered_channel_" + std::to_string(c)).c_str(), ratio);
        EXPECT_NEAR(ratio, 1.0, 5e-3) << c;
    }
    const std::vector<float> map = renderer.receivers().download(0);
    const std::vector<float> fluence = renderer.photonStage()->downloadFluence();
    render::PhotonStats stats;
    renderer.relight(stats);
    EXPECT_EQ(renderer.receivers().download(0), map);
    EXPECT_EQ(renderer.photonStage()->downloadFluence(), fluence);
    EXPECT_GT(test::channelMean(fluence, 1), 0.0);
}

}  // namespace
}  // namespace eikon
