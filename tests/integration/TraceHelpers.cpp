#include "tests/integration/TraceHelpers.h"

#include "verify/accuracy/CaseScenes.h"
#include "render/graph/FrameRenderer.h"
#include "sim/voxelize/AnalyticVoxelizer.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <fstream>
#include <numbers>

namespace eikon::test {

Scene emptyScene(glm::dvec3 boundsMin, glm::dvec3 boundsMax, int resolution) {
    Scene scene = accuracy::boxScene(boundsMin, boundsMax);
    scene.grid.resolution = glm::ivec3(resolution);
    return scene;
}

ReceiverDesc floorReceiver(double y, double size, int resolution) { return accuracy::floorReceiver(y, size, resolution); }

LightDesc directionalLight(glm::dvec3 direction, double irradiance) {
    LightDesc light;
    light.kind = LightDesc::Kind::Directional;
    light.direction = glm::normalize(direction);
    light.irradiance = Rgb(irradiance);
    return light;
}

Scene inverseSquareScene() {
    Scene scene = emptyScene(glm::dvec3(-0.6, -0.55, -0.6), glm::dvec3(0.6, 0.6, 0.6), 24);
    LightDesc light;
    light.position = glm::dvec3(0.0, 0.5, 0.0);
    light.power = Rgb(4.0 * std::numbers::pi);
    scene.lights.push_back(light);
    scene.receivers.push_back(floorReceiver(-0.5, 1.0, 32));
    return scene;
}

TraceResult traceFields(const Scene& scene, const FieldSet& fields, render::PhotonProgramOptions options) {
    return traceFields(scene, fields, render::RendererOptions{.photons = options});
}

TraceResult traceFields(const Scene& scene, const FieldSet& fields, render::RendererOptions options) {
    glContext();
    options.tracePhotons = true;
    render::FrameRenderer renderer(scene, fields, options);
    TraceResult result;
    result.stats = renderer.render(fields).photons;
    if (!scene.receivers.empty()) result.map = renderer.receivers().download(0);
    result.fluence = renderer.photonStage()->downloadFluence();
    result.paths = renderer.photonStage()->downloadPaths();
    result.pathPower = renderer.photonStage()->downloadPathPower();
    EXPECT_LT(result.stats.balanceError(), 1e-3);
    for (float value : result.map) EXPECT_TRUE(std::isfinite(value)) << "receiver map";
    for (float value : result.fluence) EXPECT_TRUE(std::isfinite(value)) << "fluence";
    return result;
}

TraceResult trace(const Scene& scene, render::PhotonProgramOptions options) {
    return traceFields(scene, sim::voxelizeScene(scene), options);
}

double channelMean(const std::vector<float>& map, int channel) {
    double sum = 0.0;
    for (std::size_t i = static_cast<std::size_t>(channel); i < map.size(); i += 3) sum += map[i];
    return sum / static_cast<double>(map.size() / 3);
}

ObjectDesc meshObject(const TriangleMesh& mesh, const std::string& name, double index) {
    const std::string path = testing::TempDir() + "/" + name;
    std::ofstream obj(path);
    obj.precision(17);
    for (const glm::dvec3& v : mesh.vertices) obj << "v " << v.x << " " << v.y << " " << v.z << "\n";
    for (const glm::ivec3& t : mesh.triangles) obj << "f " << t.x + 1 << " " << t.y + 1 << " " << t.z + 1 << "\n";
    obj.close();
    EXPECT_TRUE(obj) << path;
    ObjectDesc object;
    object.kind = ObjectDesc::Kind::Mesh;
    object.mesh.path = path;
    object.material.index = index;
    return object;
}

}  // namespace eikon::test
