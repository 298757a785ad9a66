// Where photons are aimed: the union of what the scene states the extent of,
// or the whole grid where media or shapes only the field grids know may be.
#include "render/stages/PhotonEmission.h"

#include <gtest/gtest.h>

namespace eikon {
namespace {

Scene sphereScene() {
    Scene scene;
    scene.grid.boundsMin = glm::dvec3(-1.0);
    scene.grid.boundsMax = glm::dvec3(1.0);
    ObjectDesc sphere;
    sphere.sphere = {glm::dvec3(0.2, 0.3, 0.0), 0.1};
    sphere.material.index = 1.5;
    scene.objects.push_back(sphere);
    return scene;
}

void expectBox(const render::Box& box, glm::dvec3 min, glm::dvec3 max) {
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_NEAR(box.min[axis], min[axis], 1e-12) << axis;
        EXPECT_NEAR(box.max[axis], max[axis], 1e-12) << axis;
    }
}

TEST(EmissionRegion, SpheresAndStrokesStateTheirExtent) {
    Scene scene = sphereScene();
    expectBox(render::emissionRegion(scene), {0.1, 0.2, -0.1}, {0.3, 0.4, 0.1});
    PaintStroke stroke;  // reaches 4σ = 2 radii from its path
    stroke.path = {glm::dvec3(-0.5, 0.0, 0.0), glm::dvec3(-0.4, 0.0, 0.0)};
    stroke.radius = 0.05;
    stroke.extinction = Rgb(1.0);
    scene.paint.push_back(stroke);
    expectBox(render::emissionRegion(scene), {-0.6, -0.1, -0.1}, {0.3, 0.4, 0.1});
}

TEST(EmissionRegion, MediaAndShapesOnlyTheFieldsKnowTakeTheGrid) {
    const glm::dvec3 gridMin(-1.0), gridMax(1.0);
    Scene withMesh = sphereScene();
    ObjectDesc mesh;
    mesh.kind = ObjectDesc::Kind::Mesh;
    withMesh.objects.push_back(mesh);
    expectBox(render::emissionRegion(withMesh), gridMin, gridMax);

    Scene withFluid = sphereScene();
    withFluid.sim = SimDesc{};
    expectBox(render::emissionRegion(withFluid), gridMin, gridMax);

    Scene withSmoke = sphereScene();
    withSmoke.medium.extinction = Rgb(0.1);
    expectBox(render::emissionRegion(withSmoke), gridMin, gridMax);
}

}  // namespace
}  // namespace eikon
