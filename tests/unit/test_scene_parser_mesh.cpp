// Mesh and water objects, their deformers, and the top-level frame_time.
#include "io/scene/SceneParser.h"

#include "tests/unit/SceneParserTestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace eikon {
namespace {

using namespace test;

const char* const kTetrahedron = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

json sceneWithObject(const json& object) {
    json root = validScene();
    root["objects"] = json::array({object});
    return root;
}

json meshObject(const json& deformer = nullptr) {
    json object = {{"type", "mesh"},
                   {"mesh", {{"path", writeTempFile(std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_tetra.off", kTetrahedron)}, {"translate", {0, 0.1, 0}},
                             {"rotate_deg", {0, 90, 0}}, {"scale", 0.5}}},
                   {"index", 1.5},
                   {"extinction", {0.1, 0.2, 0.3}}};
    if (!deformer.is_null()) object["deformer"] = deformer;
    return object;
}

TEST(SceneParserMesh, ParsesAMeshWithPlacementMaterialAndTwist) {
    const Scene scene = parseScene(
        sceneWithObject(meshObject({{"type", "twist"}, {"origin", {0, 0, 0}}, {"axis", {0, 2, 0}},
                                    {"keys", {{{"time", 0}, {"deg_per_m", 0}}, {{"time", 1}, {"deg_per_m", 90}}}}})),
        "test.json");
    ASSERT_EQ(scene.objects.size(), 1u);
    const ObjectDesc& object = scene.objects[0];
    EXPECT_EQ(object.kind, ObjectDesc::Kind::Mesh);
    EXPECT_NE(object.mesh.path.find("tetra.off"), std::string::npos);
    EXPECT_EQ(object.mesh.placement.translate, glm::dvec3(0, 0.1, 0));
    EXPECT_EQ(object.mesh.placement.rotateDeg, glm::dvec3(0, 90, 0));
    EXPECT_EQ(object.mesh.placement.scale, 0.5);
    EXPECT_EQ(object.material.index, 1.5);
    EXPECT_EQ(object.material.extinction, Rgb(0.1, 0.2, 0.3));
    EXPECT_EQ(object.mesh.deformer.kind, DeformerDesc::Kind::Twist);
    EXPECT_EQ(object.mesh.deformer.axis, glm::dvec3(0, 1, 0)) << "normalised";
    ASSERT_EQ(object.mesh.deformer.amount.size(), 2u);
    EXPECT_EQ(object.mesh.deformer.amount[1].value, 90.0);
    EXPECT_NEAR(scene.frameTime, 1.0 / 30.0, 1e-15) << "the default frame time";
}

TEST(SceneParserMesh, ParsesArapHandlesAndRigidKeys) {
    json arap = {{"type", "arap"},
                 {"iterations", 4},
                 {"handles",
                  {{{"min", {-1, -1, -1}}, {"max", {0.1, 1, 1}}},
                   {{"min", {0.9, -1, -1}}, {"max", {2, 1, 1}},
                    {"keys", {{{"time", 0}}, {{"time", 2}, {"translate", {0, 0.2, 0}}, {"rotate_deg", {0, 0, 30}}}}}}}}};
    const Scene scene = parseScene(sceneWithObject(meshObject(arap)), "test.json");
    const DeformerDesc& d = scene.objects[0].mesh.deformer;
    EXPECT_EQ(d.kind, DeformerDesc::Kind::Arap);
    EXPECT_EQ(d.iterations, 4);
    ASSERT_EQ(d.handles.size(), 2u);
    EXPECT_TRUE(d.handles[0].keys.empty());
    ASSERT_EQ(d.handles[1].keys.size(), 2u);
    EXPECT_EQ(d.handles[1].keys[1].pose.rotateDeg, glm::dvec3(0, 0, 30));

    const Scene rigid = parseScene(
        sceneWithObject(meshObject({{"type", "rigid"}, {"keys", {{{"time", 0.5}, {"scale", 2}}}}})), "test.json");
    EXPECT_EQ(rigid.objects[0].mesh.deformer.keys[0].pose.scale, 2.0);
}

TEST(SceneParserMesh, ParsesWaterWithDefaultsAndInputs) {
    json water = {{"type", "water"},
                  {"basin", {{"min", {-0.5, -0.2, -0.5}}, {"max", {0.5, 0.1, 0.5}}}},
                  {"swell", {{"amplitude", 0.002}, {"wavelength", 0.1}}},
                  {"drops", {{{"time", 0.1}, {"position", {0.1, 0.2}}}}},
                  {"disturbances", {{{"start", {0, 0}}, {"velocity", {0.1, 0}}, {"until", 1}}}},
                  {"index", 1.333}};
    json root = sceneWithObject(water);
    root["frame_time"] = 0.05;
    const Scene scene = parseScene(root, "test.json");
    const WaterDesc& w = scene.objects[0].water;
    EXPECT_EQ(scene.objects[0].kind, ObjectDesc::Kind::Water);
    EXPECT_EQ(w.basinMax.y, 0.1);
    EXPECT_EQ(w.cells, glm::ivec2(128, 128));
    EXPECT_EQ(w.swellAmplitude, 0.002);
    ASSERT_EQ(w.drops.size(), 1u);
    EXPECT_EQ(w.drops[0].position, glm::dvec2(0.1, 0.2));
    ASSERT_EQ(w.disturbances.size(), 1u);
    EXPECT_EQ(w.disturbances[0].until, 1.0);
    EXPECT_EQ(w.device, ComputeDevice::Auto);
    EXPECT_EQ(scene.frameTime, 0.05);
    water["device"] = "gpu";
    EXPECT_EQ(parseScene(sceneWithObject(water), "test.json").objects[0].water.device, ComputeDevice::Gpu);
}

TEST(SceneParserMesh, BadValuesNameTheirJsonPath) {
    json missing = meshObject();
    missing["mesh"]["path"] = "no_such_mesh.obj";
    expectErrorAt(sceneWithObject(missing), "objects[0].mesh.path", "an existing mesh file");

    expectErrorAt(sceneWithObject(meshObject({{"type", "twist"},
                                              {"keys", {{{"time", 1}, {"deg_per_m", 0}}, {{"time", 1}, {"deg_per_m", 9}}}}})),
                  "objects[0].deformer.keys[1].time", "increasing time");
    expectErrorAt(sceneWithObject(meshObject({{"type", "bend"}, {"axis", {0, 1, 0}}, {"toward", {0, -3, 0}},
                                              {"keys", {{{"time", 0}, {"deg_per_m", 10}}}}})),
                  "objects[0].deformer.toward", "not parallel to the axis");
    expectErrorAt(sceneWithObject(meshObject({{"type", "arap"}, {"handles", json::array()}})),
                  "objects[0].deformer.handles", "at least one handle");
    expectErrorAt(sceneWithObject(meshObject({{"type", "melt"}})), "objects[0].deformer.type");

    json water = {{"type", "water"}, {"basin", {{"min", {0, 0, 0}}, {"max", {1, 1, 1}}}}, {"cells", {2, 5}}, {"index", 1.3}};
    expectErrorAt(sceneWithObject(water), "objects[0].cells[0]", "integer in [3, 4096]");
    water["cells"] = {8, 8};
    water["drops"] = {{{"time", 0}, {"position", {1, 2, 3}}}};
    expectErrorAt(sceneWithObject(water), "objects[0].drops[0].position", "2 numbers");
    water.erase("drops");
    water["device"] = "tpu";
    expectErrorAt(sceneWithObject(water), "objects[0].device", "one of");

    json withSim = validScene();
    withSim["sim"] = json::object();
    withSim["frame_time"] = 0.1;
    expectErrorAt(withSim, "frame_time", "sim.frame_time");
}

// Every object is sharp unless it says smooth, with Fresnel on; meshes and
// water as spheres and boxes; at most 32 sharp objects.
TEST(SceneParserMesh, SurfaceKeys) {
    json root = validScene();
    root["objects"][0]["surface"] = "smooth";
    root["objects"][1]["fresnel"] = false;
    const Scene scene = parseScene(root, "test.json");
    EXPECT_FALSE(scene.objects[0].isSharp());
    EXPECT_TRUE(scene.objects[1].isSharp());
    EXPECT_FALSE(scene.objects[1].fresnel);
    EXPECT_TRUE(parseScene(validScene(), "test.json").objects[0].isSharp()) << "sharp by default";
    const ObjectDesc sharpMesh = parseScene(sceneWithObject(meshObject()), "test.json").objects[0];
    EXPECT_TRUE(sharpMesh.isSharp()) << "meshes too";
    EXPECT_TRUE(sharpMesh.hasTriangleSurface());
    json mesh = meshObject();
    mesh["surface"] = "smooth";
    mesh["fresnel"] = false;
    const ObjectDesc smoothMesh = parseScene(sceneWithObject(mesh), "test.json").objects[0];
    EXPECT_FALSE(smoothMesh.isSharp());
    EXPECT_FALSE(smoothMesh.hasTriangleSurface());
    EXPECT_FALSE(smoothMesh.fresnel);
    EXPECT_FALSE(scene.objects[1].hasTriangleSurface()) << "a sphere is an exact shape";

    root["objects"][0]["surface"] = "glassy";
    expectErrorAt(root, "objects[0].surface", "\"sharp\"");
    mesh["surface"] = "glassy";
    expectErrorAt(sceneWithObject(mesh), "objects[0].surface", "\"sharp\"");
    json many = validScene();
    many["objects"] = json::array();
    for (int k = 0; k < 33; ++k)
        many["objects"].push_back({{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 0.1}, {"index", 1.5}});
    expectErrorAt(many, "objects", "at most 32 sharp");
}

// The receivers fill a uniform block of 128 (bridge/layout/GpuLayouts.h).
TEST(SceneParserMesh, AtMost128Receivers) {
    json root = validScene();
    const json receiver = root["receivers"][0];
    root["receivers"] = json::array();
    for (int k = 0; k < 128; ++k) root["receivers"].push_back(receiver);
    EXPECT_EQ(parseScene(root, "test.json").receivers.size(), 128u);
    root["receivers"].push_back(receiver);
    expectErrorAt(root, "receivers", "at most 128 receivers");
}

TEST(SceneParserMesh, ReceiverFilter) {
    json root = validScene();
    EXPECT_EQ(parseScene(root, "test.json").receivers[0].filter, ReceiverDesc::Filter::Binomial);
    root["receivers"][0]["filter"] = "none";
    EXPECT_EQ(parseScene(root, "test.json").receivers[0].filter, ReceiverDesc::Filter::None);
    root["receivers"][0]["filter"] = "gaussian";
    expectErrorAt(root, "receivers[0].filter", "\"binomial\"");
}

}  // namespace
}  // namespace eikon
