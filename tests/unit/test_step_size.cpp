// shaders/common/step_size.glsl and sharp_surfaces.glsl compiled as C++
// (through cpp_shim.h): the octree step reaches just past the far face of
// the node around x, within [Δs_min, the node's cap]; a camera ray's step
// crosses step_voxels voxels along each axis; sharp surfaces are met where
// they are.
#include "shaders/common/cpp_shim.h"

#include <gtest/gtest.h>

#include <cmath>

namespace eikon {
namespace {

using shader::vec3;

TEST(StepSize, BoxExitAlongAnAxis) {
    EXPECT_FLOAT_EQ(shader::box_exit_distance(vec3(0.25f), vec3(1.0f, 0.0f, 0.0f), vec3(0.0f), vec3(1.0f)), 0.75f);
    EXPECT_FLOAT_EQ(shader::box_exit_distance(vec3(0.25f), vec3(0.0f, -1.0f, 0.0f), vec3(0.0f), vec3(1.0f)), 0.25f);
}

TEST(StepSize, BoxExitOnTheDiagonalMeetsTheNearestFace) {
    const vec3 d = glm::normalize(vec3(1.0f, 2.0f, 0.0f));
    // y reaches its face (1 − 0.5 = 0.5) first, after 0.5 / d.y.
    EXPECT_NEAR(shader::box_exit_distance(vec3(0.5f), d, vec3(0.0f), vec3(1.0f)), 0.5f / d.y, 1e-6f);
}

TEST(StepSize, OctreeStepCrossesTheNodeFace) {
    const vec3 voxel(0.1f);
    // Level 2: nodes of 4 voxels (0.4 m); from 0.05 along +x the face is at 0.4.
    const float step = shader::octree_step(vec3(0.05f), vec3(1.0f, 0.0f, 0.0f), vec3(0.0f), voxel, 2.0f, 0.01f, 1.0f);
    EXPECT_NEAR(step, 0.35f + 1e-4f, 1e-6f);
}

TEST(StepSize, OctreeStepIsClamped) {
    const vec3 voxel(0.1f);
    const vec3 x(0.05f);
    const vec3 d(1.0f, 0.0f, 0.0f);
    EXPECT_FLOAT_EQ(shader::octree_step(x, d, vec3(0.0f), voxel, 2.0f, 0.01f, 0.2f), 0.2f);
    EXPECT_FLOAT_EQ(shader::octree_step(x, d, vec3(0.0f), voxel, 0.0f, 0.08f, 1.0f), 0.08f);
}

// A camera ray's step on cubic voxels is step_voxels edges whatever its
// direction and bend: the isotropic step, unchanged.
TEST(StepSize, VoxelCrossingStepOnCubicVoxelsIsTheIsotropicStep) {
    const float reach = 2.0f * 0.0125f;
    for (const vec3& d : {vec3(1.0f, 0.0f, 0.0f), glm::normalize(vec3(1.0f, 1.0f, 1.0f)), glm::normalize(vec3(0.1f, -3.0f, 2.0f))})
        for (const vec3& bend : {vec3(0.0f), vec3(0.0f, 40.0f, 0.0f)})
            EXPECT_EQ(shader::voxel_crossing_step(d, bend, vec3(reach), reach, reach), reach);
}

// On flat voxels (16 m × 2 cm × 47 m, scenes/hot_road_mirage.json) a ray
// 5 mrad off level crosses one 2 cm layer in 4 m: the step is that, not 2 cm.
TEST(StepSize, VoxelCrossingStepCrossesOneLayerOfFlatVoxels) {
    const vec3 reach(16.0f, 0.02f, 46.875f);
    const vec3 d = glm::normalize(vec3(0.0f, -0.005f, -1.0f));
    EXPECT_NEAR(shader::voxel_crossing_step(d, vec3(0.0f), reach, 0.02f, 46.875f), 0.02f / std::abs(d.y), 1e-4f);
}

// Where the ray levels off its bend, counted four times, limits the step:
// 2·|bend|·s² = one layer. The step never exceeds step_voxels of the
// largest edge.
TEST(StepSize, VoxelCrossingStepOfALevelRayIsBoundByItsBend) {
    const vec3 reach(16.0f, 0.02f, 46.875f);
    const vec3 level(0.0f, 0.0f, -1.0f);
    const float bend = 2.4e-4f;  // 1/m: the hot road's at the asphalt
    EXPECT_NEAR(shader::voxel_crossing_step(level, vec3(0.0f, bend, 0.0f), reach, 0.02f, 46.875f),
                std::sqrt(0.02f / (2.0f * bend)), 1e-3f);
    EXPECT_FLOAT_EQ(shader::voxel_crossing_step(level, vec3(0.0f), reach, 0.02f, 46.875f), 46.875f);
}

// shaders/common/sharp_surfaces.glsl as C++: crossings from outside and
// inside, the point put on the surface and its outward normal.
TEST(SharpSurfaceMath, SphereAndBoxCrossings) {
    using shader::vec4;
    const vec4 sphereA(0.0f, 0.0f, 0.0f, 0.0f), sphereB(0.5f, 0.0f, 0.0f, 0.0f);
    const vec3 down(0.0f, -1.0f, 0.0f);
    EXPECT_NEAR(shader::surface_crossing(sphereA, sphereB, vec3(0.0f, 2.0f, 0.0f), down, false, 1e-6f), 1.5f, 1e-6f);
    EXPECT_NEAR(shader::surface_crossing(sphereA, sphereB, vec3(0.0f), down, true, 1e-6f), 0.5f, 1e-6f);
    EXPECT_EQ(shader::surface_crossing(sphereA, sphereB, vec3(1.0f, 2.0f, 0.0f), down, false, 1e-6f),
              shader::EIKON_NO_CROSSING);
    const vec3 on = shader::onto_surface(sphereA, sphereB, vec3(0.0f, 0.5001f, 0.0f));
    EXPECT_NEAR(on.y, 0.5f, 1e-7f);
    EXPECT_NEAR(shader::surface_normal(sphereA, sphereB, on).y, 1.0f, 1e-6f);

    const vec4 boxA(-1.0f, -1.0f, -1.0f, 1.0f), boxB(1.0f, 0.0f, 1.0f, 0.0f);
    EXPECT_TRUE(shader::inside_shape(boxA, boxB, vec3(0.0f, -0.5f, 0.0f)));
    EXPECT_NEAR(shader::surface_crossing(boxA, boxB, vec3(0.2f, 1.0f, 0.0f), down, false, 1e-6f), 1.0f, 1e-6f);
    EXPECT_NEAR(shader::surface_crossing(boxA, boxB, vec3(0.2f, -0.25f, 0.0f), down, true, 1e-6f), 0.75f, 1e-6f);
    const vec3 n = shader::surface_normal(boxA, boxB, vec3(0.2f, 0.0f, 0.3f));
    EXPECT_EQ(n, vec3(0.0f, 1.0f, 0.0f));
}

// Vector Snell: sin θ′ = sin θ / n going in; the mirror keeps the tangent.
TEST(SharpSurfaceMath, RefractionObeysSnell) {
    const float theta = 0.6f;
    const vec3 d(std::sin(theta), -std::cos(theta), 0.0f);
    const vec3 up(0.0f, 1.0f, 0.0f);
    const vec3 t = shader::refracted_direction(d, up, 1.0f, 1.5f);
    EXPECT_NEAR(t.x, std::sin(theta) / 1.5f, 1e-6f);
    EXPECT_NEAR(glm::length(t), 1.0f, 1e-6f);
    const vec3 m = shader::mirrored_direction(d, up);
    EXPECT_NEAR(m.x, d.x, 1e-7f);
    EXPECT_NEAR(m.y, -d.y, 1e-7f);
}

// Where tracers read a sharp object's voxelised optics: a point within the
// margin of a sphere or box moves along the normal to the margin off the
// surface, on the side it is on; one further off stays put.
TEST(SharpSurfaceMath, PointsNearASurfaceMoveOffItToTheirOwnSide) {
    using shader::vec4;
    const vec4 sphereA(0.0f, 0.0f, 0.0f, 0.0f), sphereB(0.5f, 0.0f, 0.0f, 0.0f);
    const float margin = 0.1f;
    EXPECT_NEAR(glm::length(shader::off_the_surface(sphereA, sphereB, vec3(0.3f, 0.3f, 0.0f), true, margin)), 0.4f, 1e-6f);
    EXPECT_NEAR(glm::length(shader::off_the_surface(sphereA, sphereB, vec3(0.0f, 0.51f, 0.0f), false, margin)), 0.6f, 1e-6f);
    EXPECT_EQ(shader::off_the_surface(sphereA, sphereB, vec3(0.0f, 0.2f, 0.0f), true, margin), vec3(0.0f, 0.2f, 0.0f));
    EXPECT_EQ(shader::off_the_surface(sphereA, sphereB, vec3(0.0f, 0.7f, 0.0f), false, margin), vec3(0.0f, 0.7f, 0.0f));
    EXPECT_EQ(shader::off_the_surface(sphereA, vec4(0.05f, 0.0f, 0.0f, 0.0f), vec3(0.0f, 0.04f, 0.0f), true, margin),
              vec3(0.0f)) << "a sphere narrower than the margin: its centre";

    const vec4 boxA(-1.0f, -1.0f, -1.0f, 1.0f), boxB(1.0f, 0.0f, 1.0f, 0.0f);
    const vec3 inside = shader::off_the_surface(boxA, boxB, vec3(0.95f, -0.05f, 0.2f), true, margin);
    EXPECT_NEAR(inside.x, 0.9f, 1e-6f);
    EXPECT_NEAR(inside.y, -0.1f, 1e-6f);
    EXPECT_NEAR(inside.z, 0.2f, 1e-6f);
    const vec3 above = shader::off_the_surface(boxA, boxB, vec3(0.2f, 0.03f, 0.3f), false, margin);
    EXPECT_NEAR(above.y, 0.1f, 1e-6f);
    EXPECT_NEAR(above.x, 0.2f, 1e-6f);
    const vec3 onFace = shader::off_the_surface(boxA, boxB, vec3(0.2f, 0.0f, 0.3f), false, margin);
    EXPECT_NEAR(onFace.y, 0.1f, 1e-6f);
}

}  // namespace
}  // namespace eikon
