#include "sim/voxelize/AnalyticVoxelizer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace eikon::sim {
namespace {

Scene sceneWith(ObjectDesc object, int resolution) {
    Scene scene;
    scene.grid.resolution = glm::ivec3(resolution);
    scene.grid.boundsMin = glm::dvec3(-1.0);
    scene.grid.boundsMax = glm::dvec3(1.0);
    scene.medium.index = 1.0;
    scene.objects.push_back(object);
    return scene;
}

// Smooth objects: their index is voxelized (sharp ones keep it for the tracer).
ObjectDesc sphere(double radius, double index) {
    ObjectDesc object;
    object.kind = ObjectDesc::Kind::Sphere;
    object.surface = ObjectDesc::Surface::Smooth;
    object.sphere = {glm::dvec3(0.1, -0.05, 0.02), radius};
    object.material.index = index;
    return object;
}

// Σ coverage · h³ against the analytic volume: 4³ supersampling at 64³
// should be well within 1% ([Sun08] §4.1 uses 4³).
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
    box.surface = ObjectDesc::Surface::Smooth;
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

}  // namespace
}  // namespace eikon::sim
