#include "sim/voxelize/AnalyticVoxelizer.h"
#include "sim/voxelize/GaussianSmoothing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <numeric>

namespace eikon::sim {
namespace {

Scene sceneWith(ObjectDesc object, int resolution) {
    Scene scene;
    scene.grid.resolution = glm::ivec3(resolution);
    scene.grid.boundsMin = glm::dvec3(-1.0);
    scene.grid.boundsMax = glm::dvec3(1.0);
    scene.grid.smoothingSigmaVoxels = 0.0;
    scene.medium.index = 1.0;
    scene.objects.push_back(object);
    return scene;
}

ObjectDesc sphere(double radius, double index) {
    ObjectDesc object;
    object.kind = ObjectDesc::Kind::Sphere;
    object.sphere = {glm::dvec3(0.1, -0.05, 0.02), radius};
    object.material.index = index;
    return object;
}

// Σ coverage · h³ against the analytic volume: 4³ supersampling at 64³
// should be well within 1% (Sun et al. 2008, §4.1, use 4³).
TEST(AnalyticVoxelizer, SphereVolumeWithinOnePercent) {
    const Scene scene = sceneWith(sphere(0.6, 1.5), 64);
    const FieldSet fields = voxelizeScene(scene);
    double coveredVolume = 0.0;
    for (float delta : fields.deltaIndex) coveredVolume += delta / 0.5 * fields.grid.voxelVolume();
    const double exact = 4.0 / 3.0 * std::numbers::pi * std::pow(0.6, 3);
    EXPECT_NEAR(coveredVolume / exact, 1.0, 0.01);
}

TEST(AnalyticVoxelizer, BoxCoverageIsExactForAlignedFaces) {
    ObjectDesc box;
    box.kind = ObjectDesc::Kind::Box;
    box.box = {glm::dvec3(-0.5), glm::dvec3(0.5, 0.5, 0.25)};  // faces on voxel boundaries of an 8³ grid
    box.material.index = 2.0;
    box.material.extinction = Rgb(1.0, 2.0, 3.0);
    const FieldSet fields = voxelizeScene(sceneWith(box, 8));
    EXPECT_FLOAT_EQ(fields.deltaIndex[fields.grid.linearIndex(3, 3, 3)], 1.0f);
    EXPECT_FLOAT_EQ(fields.deltaIndex[fields.grid.linearIndex(0, 3, 3)], 0.0f);
    EXPECT_FLOAT_EQ(fields.extinction[3 * fields.grid.linearIndex(3, 3, 3) + 2], 3.0f);
    EXPECT_FALSE(fields.hasScattering()) << "no scattering anywhere: the field is not created";
}

TEST(AnalyticVoxelizer, LaterObjectReplacesEarlierWhereItCovers) {
    Scene scene = sceneWith(sphere(0.9, 1.5), 16);
    ObjectDesc inner = sphere(0.3, 1.2);
    scene.objects.push_back(inner);
    const FieldSet fields = voxelizeScene(scene);
    EXPECT_NEAR(fields.deltaIndex[fields.grid.linearIndex(8, 8, 8)], 0.2f, 1e-6f);
}

TEST(GaussianSmoothing, PaperKernelIsNineWideAndNormalised) {
    const auto kernel = gaussianKernel(1.5);
    EXPECT_EQ(kernel.size(), 9u);
    EXPECT_NEAR(std::accumulate(kernel.begin(), kernel.end(), 0.0), 1.0, 1e-12);
    EXPECT_NEAR(kernel[4] / kernel[3], std::exp(0.5 / (1.5 * 1.5)), 1e-12);
}

// A single spike on a 9³ grid, far from the edges, spreads into the
// separable product of the kernel and keeps its sum.
TEST(GaussianSmoothing, SpikeBecomesProductKernel) {
    std::vector<float> values(9 * 9 * 9, 0.0f);
    values[4 + 9 * (4 + 9 * 4)] = 1.0f;
    gaussianSmooth(values, glm::ivec3(9), 0.7);
    const auto kernel = gaussianKernel(0.7);  // radius 2
    EXPECT_NEAR(std::accumulate(values.begin(), values.end(), 0.0), 1.0, 1e-6);
    EXPECT_NEAR(values[5 + 9 * (4 + 9 * 3)], kernel[3] * kernel[2] * kernel[1], 1e-7);
}

TEST(GaussianSmoothing, ConstantFieldUnchangedAtEdges) {
    std::vector<float> values(5 * 4 * 3, 0.25f);
    gaussianSmooth(values, glm::ivec3(5, 4, 3), 1.5);
    for (float value : values) EXPECT_NEAR(value, 0.25f, 1e-6f);
}

}  // namespace
}  // namespace eikon::sim
