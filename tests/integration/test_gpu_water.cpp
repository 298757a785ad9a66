// A water body on the GPU (sim/gpu/GpuWaterBody.h) against the host path
// it replaces: the same scene advanced frame by frame on both, its surface's
// triangles and tree and the attenuation its coverage paints compared
// value by value, and nothing read back.
#include "sim/SceneFields.h"

#include "bridge/core/Error.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace eikon::sim {
namespace {

// pool_caustics in small: a swell, a drop during frame 1 and, with
// `disturbance`, a mover crossing the pool.
Scene pool(bool disturbance, ComputeDevice device) {
    Scene scene;
    scene.grid.resolution = glm::ivec3(32, 16, 32);
    scene.grid.boundsMin = glm::dvec3(-0.5, 0.0, -0.5);
    scene.grid.boundsMax = glm::dvec3(0.5, 0.5, 0.5);
    scene.frameTime = 0.04;
    ObjectDesc water;
    water.kind = ObjectDesc::Kind::Water;
    water.water.basinMin = glm::dvec3(-0.52, -0.02, -0.52);
    water.water.basinMax = glm::dvec3(0.52, 0.3, 0.52);
    water.water.cells = glm::ivec2(41, 37);
    water.water.waveSpeed = 0.4;
    water.water.damping = 0.1;
    water.water.swellAmplitude = 0.003;
    water.water.swellWavelength = 0.12;
    water.water.seed = 7;
    water.water.drops.push_back({0.02, {0.15, -0.1}, 0.004, 0.015});
    if (disturbance) water.water.disturbances.push_back({{-0.3, 0.0}, {2.0, 0.5}, 0.0, 1e30, 2.0, 0.03});
    water.water.device = device;
    water.material.index = 1.333;
    water.material.extinction = Rgb(0.45, 0.06, 0.03);
    scene.objects.push_back(water);
    return scene;
}

std::vector<float> download(GLuint buffer, std::size_t floats) {
    std::vector<float> values(floats);
    glGetNamedBufferSubData(buffer, 0, static_cast<GLsizeiptr>(floats * sizeof(float)), values.data());
    return values;
}

struct Differences {
    double heights = 0.0;  // m
    float positions = 0.0f, normals = 0.0f, nodes = 0.0f, extinction = 0.0f;
};

Differences compare(const SceneFields& host, const SceneFields& device) {
    const FieldSet& h = host.fields();
    const gpu::GpuWaterBody& water = *device.gpuWater();
    const std::vector<float> triangles = download(water.surfaceTriangles().id(), h.surfaceTriangles.size());
    const std::vector<float> nodes = download(water.surfaceNodes().id(), h.surfaceNodes.size());
    const std::vector<float> extinction = download(water.extinction(), h.extinction.size());
    Differences d;
    // The host's surface nodes are the first vertices of its water mesh, at the rest level plus h.
    const std::vector<double> heights = water.downloadHeights();
    const TriangleMesh& mesh = *host.deformedMeshes()[0];
    const double rest = 0.3;  // pool()'s basin top
    for (std::size_t n = 0; n < heights.size(); ++n)
        d.heights = std::max(d.heights, std::abs((rest + heights[n]) - mesh.vertices[n].y));
    for (std::size_t i = 0; i < triangles.size(); ++i) {
        const float difference = std::abs(triangles[i] - h.surfaceTriangles[i]);
        const bool normal = (i % kSurfaceTriangleFloats) >= 12;
        (normal ? d.normals : d.positions) = std::max(normal ? d.normals : d.positions, difference);
    }
    for (std::size_t i = 0; i < nodes.size(); ++i) d.nodes = std::max(d.nodes, std::abs(nodes[i] - h.surfaceNodes[i]));
    for (std::size_t i = 0; i < extinction.size(); ++i)
        d.extinction = std::max(d.extinction, std::abs(extinction[i] - h.extinction[i]));
    return d;
}

class GpuWaterTest : public ::testing::Test {
protected:
    void SetUp() override { test::glContext(); }
};

// Every pass is the host's float64 arithmetic in the same order (exp and
// acos, which GLSL lacks in float64, of the GPU's own to an ulp or two), so
// heights, corners, normals, tree boxes and the κ the coverage paints agree
// to float rounding: on llvmpipe, bit for bit (GLSL promises float64
// division and sqrt less exactly than IEEE, hence the bounds).
TEST_F(GpuWaterTest, FramesMatchTheHostPathToFloatRounding) {
    SceneFields host(pool(false, ComputeDevice::Cpu)), device(pool(false, ComputeDevice::Gpu));
    EXPECT_EQ(host.placeWater(true), "cpu");
    ASSERT_EQ(device.placeWater(false), "gpu") << "device \"gpu\" runs there under a software rasterizer too";
    for (int frame = 0; frame < 4; ++frame) {
        const Differences d = compare(host, device);
        EXPECT_LE(d.heights, 1e-15) << "frame " << frame << ": m, against ripples of millimetres";
        EXPECT_LE(d.positions, 3e-8f) << "frame " << frame << ": one float32 ulp at 0.3 m";
        EXPECT_LE(d.nodes, 3e-8f) << "frame " << frame;
        EXPECT_LE(d.normals, 1.2e-7f) << "frame " << frame << ": one float32 ulp of a unit vector's part";
        EXPECT_LE(d.extinction, 1e-7f) << "frame " << frame << ": 1/m, κ of at most 0.45";
        test::reportFigure("largest_height_difference_m", d.heights);
        test::reportFigure("largest_normal_difference", d.normals);
        host.advanceFrame();
        device.advanceFrame();
    }
    EXPECT_DOUBLE_EQ(device.gpuWater()->time(), host.time());
}

// A disturbance's Gaussian takes the GPU's own float64 exp.
TEST_F(GpuWaterTest, AMovingDisturbanceAgreesToFloatRounding) {
    SceneFields host(pool(true, ComputeDevice::Cpu)), device(pool(true, ComputeDevice::Gpu));
    host.placeWater(true);
    device.placeWater(true);
    Differences d;
    for (int frame = 0; frame < 4; ++frame) {
        host.advanceFrame();
        device.advanceFrame();
        d = compare(host, device);
    }
    EXPECT_LE(d.heights, 1e-15) << "m, against ripples of millimetres";
    EXPECT_LE(d.positions, 3e-8f) << "at most one float32 ulp at 0.3 m";
    EXPECT_LE(d.normals, 1.2e-7f);
    EXPECT_LE(d.extinction, 1e-7f);
    test::reportFigure("largest_height_difference_m", d.heights);
}

TEST_F(GpuWaterTest, AutoStaysOnTheCpuUnderASoftwareRasterizerAndGpuRefusesWhatItCannotTake) {
    SceneFields automatic(pool(false, ComputeDevice::Auto));
    EXPECT_EQ(automatic.placeWater(false), "cpu");
    EXPECT_EQ(automatic.gpuWater(), nullptr);
    Scene twoObjects = pool(false, ComputeDevice::Gpu);
    ObjectDesc sphere;
    sphere.kind = ObjectDesc::Kind::Sphere;
    sphere.sphere.radius = 0.1;
    twoObjects.objects.push_back(sphere);
    SceneFields refused(twoObjects);
    try {
        refused.placeWater(true);
        FAIL() << "a water body beside another object stays on the host";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("objects[0].device"), std::string::npos) << error.what();
        EXPECT_NE(std::string(error.what()).find("only object"), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace eikon::sim
