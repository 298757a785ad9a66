// shaders/common/step_size.glsl compiled as C++ (through cpp_shim.h): the
// octree step reaches just past the far face of the node around x, within
// [Δs_min, the node's cap].
#include "shaders/common/cpp_shim.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace eikon
