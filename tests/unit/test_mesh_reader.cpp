// Mesh files in every supported format, good and bad: a unit cube must come
// back closed with volume 1; truncated files, non-finite coordinates, open
// and non-manifold meshes must each give an InputError naming the file and
// the reason (with the count of offending edges).
#include "bridge/core/Error.h"
#include "io/mesh/MeshReader.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

namespace eikon::io {
namespace {

namespace fs = std::filesystem;

// Unit cube [0,1]³, quads counter-clockwise seen from outside.
const std::array<glm::dvec3, 8> kCubeVertices = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                                   {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
const std::array<std::array<int, 4>, 6> kCubeQuads = {
    {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}}};

class MeshReaderTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("eikon_mesh_reader_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string write(const std::string& name, const std::string& bytes) const {
        const fs::path path = dir_ / name;
        std::ofstream(path, std::ios::binary) << bytes;
        return path.string();
    }
    fs::path dir_;
};

std::string cubeOff(int skipFaces = 0) {
    std::ostringstream off;
    off << "OFF\n8 " << 6 - skipFaces << " 0\n";
    for (const auto& v : kCubeVertices) off << v.x << " " << v.y << " " << v.z << "\n";
    for (int f = skipFaces; f < 6; ++f)
        off << "4 " << kCubeQuads[f][0] << " " << kCubeQuads[f][1] << " " << kCubeQuads[f][2] << " " << kCubeQuads[f][3]
            << "\n";
    return off.str();
}

std::string cubeObj() {
    std::ostringstream obj;
    for (const auto& v : kCubeVertices) obj << "v " << v.x << " " << v.y << " " << v.z << "\n";
    for (const auto& q : kCubeQuads) obj << "f " << q[0] + 1 << " " << q[1] + 1 << " " << q[2] + 1 << " " << q[3] + 1 << "\n";
    return obj.str();
}

std::string cubePly() {
    std::ostringstream ply;
    ply << "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
           "element face 6\nproperty list uchar int vertex_indices\nend_header\n";
    for (const auto& v : kCubeVertices) ply << v.x << " " << v.y << " " << v.z << "\n";
    for (const auto& q : kCubeQuads) ply << "4 " << q[0] << " " << q[1] << " " << q[2] << " " << q[3] << "\n";
    return ply.str();
}

// Binary STL: 80-byte header, triangle count, 50 bytes per triangle.
std::string cubeStl(float poison = 0.0f) {
    std::string bytes(80, ' ');
    const std::uint32_t count = 12;
    bytes.append(reinterpret_cast<const char*>(&count), 4);
    for (const auto& q : kCubeQuads)
        for (const auto& t : {std::array<int, 3>{q[0], q[1], q[2]}, std::array<int, 3>{q[0], q[2], q[3]}}) {
            float record[12] = {};
            for (int c = 0; c < 3; ++c)
                for (int axis = 0; axis < 3; ++axis)
                    record[3 + 3 * c + axis] = static_cast<float>(kCubeVertices[t[c]][axis]);
            record[3] += poison;
            bytes.append(reinterpret_cast<const char*>(record), sizeof record);
            bytes.append(2, '\0');
        }
    return bytes;
}

std::string messageOf(const std::string& path, MeshClosure closure = MeshClosure::Closed) {
    try {
        readMesh(path, closure);
    } catch (const InputError& error) {
        return error.what();
    }
    return "no error";
}

TEST_F(MeshReaderTest, ReadsAClosedCubeInEveryFormat) {
    for (const auto& [name, bytes] : {std::pair{"cube.off", cubeOff()}, std::pair{"cube.obj", cubeObj()},
                                      std::pair{"cube.ply", cubePly()}, std::pair{"cube.stl", cubeStl()}}) {
        SCOPED_TRACE(name);
        const TriangleMesh mesh = readMesh(write(name, bytes));
        EXPECT_EQ(mesh.triangles.size(), 12u);
        EXPECT_EQ(mesh.vertices.size(), 8u);  // STL corners are merged into shared vertices
        EXPECT_TRUE(countEdges(mesh).closedManifold());
        EXPECT_NEAR(std::abs(enclosedVolume(mesh)), 1.0, 1e-12);
    }
}

TEST_F(MeshReaderTest, TruncatedFilesAreRefused) {
    const std::string off = cubeOff();
    const std::string offMessage = messageOf(write("cut.off", off.substr(0, off.size() / 2)));
    EXPECT_NE(offMessage.find("cut.off"), std::string::npos) << offMessage;
    EXPECT_NE(offMessage.find("truncated"), std::string::npos) << offMessage;

    const std::string ply = cubePly();
    const std::string plyMessage = messageOf(write("cut.ply", ply.substr(0, ply.size() - 20)));
    EXPECT_NE(plyMessage.find("cut.ply"), std::string::npos) << plyMessage;
    EXPECT_NE(plyMessage.find("truncated"), std::string::npos) << plyMessage;

    const std::string stl = cubeStl();
    const std::string stlMessage = messageOf(write("cut.stl", stl.substr(0, stl.size() - 75)));
    EXPECT_NE(stlMessage.find("cut.stl"), std::string::npos) << stlMessage;
    EXPECT_EQ(stlMessage.find("no error"), std::string::npos) << stlMessage;

    const std::string obj = cubeObj();
    const std::string objMessage = messageOf(write("cut.obj", obj.substr(0, obj.size() - 12)));
    EXPECT_NE(objMessage.find("cut.obj"), std::string::npos) << objMessage;
    EXPECT_EQ(objMessage.find("no error"), std::string::npos) << objMessage;

    EXPECT_NE(messageOf(write("empty.off", "")).find("empty"), std::string::npos);
}

// Headers declaring more vertices or faces than the file can hold are
// refused before anything is allocated for them, naming the file and the
// counts (OpenMesh would add faces past the end for gigabytes).
TEST_F(MeshReaderTest, DeclaredCountsBeyondTheFileAreRefusedUpFront) {
    std::string off = cubeOff();
    off.replace(off.find("8 6 0"), 5, "8 900000000 0");
    const std::string offMessage = messageOf(write("huge.off", off));
    EXPECT_NE(offMessage.find("huge.off"), std::string::npos) << offMessage;
    EXPECT_NE(offMessage.find("900000000 faces"), std::string::npos) << offMessage;
    // Past OpenMesh's int, or not a count at all (found by fuzz_mesh_off): the header itself is refused.
    for (const char* counts : {"8 2000000000 0", "4000000000 12 0\x0e0"}) {
        std::string bad = cubeOff();
        bad.replace(bad.find("8 6 0"), 5, counts);
        EXPECT_NE(messageOf(write("bad_counts.off", bad)).find("expected an OFF header"), std::string::npos) << counts;
    }

    std::string ply = cubePly();
    ply.replace(ply.find("element vertex 8"), 16, "element vertex 900000000");
    const std::string plyMessage = messageOf(write("huge.ply", ply));
    EXPECT_NE(plyMessage.find("huge.ply"), std::string::npos) << plyMessage;
    EXPECT_NE(plyMessage.find("900000000 vertices"), std::string::npos) << plyMessage;
    ply.replace(ply.find("element vertex 900000000"), 24, "element vertex 4000000000");  // past OpenMesh's int
    EXPECT_NE(messageOf(write("huger.ply", ply)).find("huger.ply: line 3"), std::string::npos);

    std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex 300000000\n"
                         "property float x\nproperty float y\nproperty float z\nend_header\n";
    binary.append(36, '\0');
    const std::string binaryMessage = messageOf(write("huge_binary.ply", binary));
    EXPECT_NE(binaryMessage.find("huge_binary.ply"), std::string::npos) << binaryMessage;
    EXPECT_NE(binaryMessage.find("300000000 vertices"), std::string::npos) << binaryMessage;

    // Binary OFF, written big-endian: OpenMesh reads the machine's order, so the counts are refused as read.
    std::string offBinary = "OFF BINARY\n";
    for (const std::uint32_t count : {8u, 2000000000u, 0u}) {
        const unsigned char be[4] = {static_cast<unsigned char>(count >> 24), static_cast<unsigned char>(count >> 16),
                                     static_cast<unsigned char>(count >> 8), static_cast<unsigned char>(count)};
        offBinary.append(reinterpret_cast<const char*>(be), 4);
    }
    offBinary.append(8 * 12 + 16, '\0');
    const std::string offBinaryMessage = messageOf(write("huge_binary.off", offBinary));
    EXPECT_NE(offBinaryMessage.find("huge_binary.off"), std::string::npos) << offBinaryMessage;
    EXPECT_NE(offBinaryMessage.find("faces (truncated"), std::string::npos) << offBinaryMessage;
}

// OpenMesh drops OBJ faces whose index overflows an int or points nowhere;
// they are refused with their line instead.
TEST_F(MeshReaderTest, ObjFaceIndicesOutOfRangeAreRefusedWithTheirLine) {
    std::string obj = cubeObj();
    obj.replace(obj.find("f 1 4 3 2"), 9, "f 1 4 3 99999999999999999999");
    const std::string hugeMessage = messageOf(write("huge_index.obj", obj));
    EXPECT_NE(hugeMessage.find("huge_index.obj: line 9"), std::string::npos) << hugeMessage;
    EXPECT_NE(hugeMessage.find("from 1 to 8"), std::string::npos) << hugeMessage;
    obj = cubeObj();
    obj.replace(obj.find("f 1 4 3 2"), 9, "f 1 4 3 9");
    EXPECT_NE(messageOf(write("past_end.obj", obj)).find("past_end.obj: line 9"), std::string::npos);
    obj = cubeObj();
    obj.replace(obj.find("f 1 4 3 2"), 9, "f -8 -5 -6 -7");  // relative indices stay valid
    EXPECT_EQ(readMesh(write("relative.obj", obj)).triangles.size(), 12u);
}

TEST_F(MeshReaderTest, NonFiniteCoordinatesAreRefusedWithTheirPlace) {
    std::string off = cubeOff();
    off.replace(off.find("1 1 0"), 5, "1 nan 0");
    const std::string textMessage = messageOf(write("nan.off", off));
    EXPECT_NE(textMessage.find("nan.off: line 5"), std::string::npos) << textMessage;
    EXPECT_NE(textMessage.find("finite"), std::string::npos) << textMessage;

    const std::string binaryMessage = messageOf(write("nan.stl", cubeStl(std::numeric_limits<float>::quiet_NaN())));
    EXPECT_NE(binaryMessage.find("nan.stl: triangle"), std::string::npos) << binaryMessage;
    EXPECT_NE(binaryMessage.find("finite corner coordinates"), std::string::npos) << binaryMessage;
}

TEST_F(MeshReaderTest, OpenMeshIsRefusedWhereClosedIsNeededWithItsEdgeCount) {
    const std::string path = write("open.off", cubeOff(1));  // the z = 0 face removed: 4 open edges
    const std::string message = messageOf(path);
    EXPECT_NE(message.find("open.off"), std::string::npos) << message;
    EXPECT_NE(message.find("4 open and 0 non-manifold edges"), std::string::npos) << message;
    EXPECT_EQ(readMesh(path, MeshClosure::Any).triangles.size(), 10u);  // fine where open is allowed
}

TEST_F(MeshReaderTest, NonManifoldEdgesAreCounted) {
    // A closed tetrahedron plus a fin on its edge 0–1: that edge is shared by three triangles.
    const std::string off = "OFF\n5 5 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n0.5 -1 0\n"
                            "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n3 0 1 4\n";
    const std::string message = messageOf(write("fin.off", off));
    EXPECT_NE(message.find("2 open and 1 non-manifold edges"), std::string::npos) << message;
}

TEST_F(MeshReaderTest, BadPathsAndExtensionsAreRefused) {
    EXPECT_NE(messageOf((dir_ / "missing.obj").string()).find("no such file"), std::string::npos);
    EXPECT_NE(messageOf(write("cube.txt", cubeOff())).find(".obj, .ply, .off or .stl"), std::string::npos);
    EXPECT_NE(messageOf(write("bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n")).find("index below 3"),
              std::string::npos);
}

// OpenMesh reads a text OFF's face counts as unsigned ints wherever the
// lines break: "-9" became 4294967287 corners and 3 GiB of pushes from a
// failed stream (found by fuzz_mesh_off). The data are walked as it reads
// them, and each bad token is refused with its line.
TEST_F(MeshReaderTest, TextOffDataAreWalkedAsOpenMeshReadsThem) {
    const std::string cube = cubeOff();
    const auto faceLine = [&](const std::string& replacement) {
        std::string off = cube;
        off.replace(off.find("\n4 ") + 1, off.find('\n', off.find("\n4 ") + 1) - off.find("\n4 ") - 1, replacement);
        return messageOf(write("face.off", off));
    };
    for (const char* face : {"0 -9 5 7", "-9 0 1 2", "2 0 1", "3.5 0 1 2", "4 0 1 2 x"}) {
        const std::string message = faceLine(face);
        EXPECT_NE(message.find("face.off: line "), std::string::npos) << face << ": " << message;
        EXPECT_TRUE(message.find("expected a corner count of 3 or more") != std::string::npos ||
                    message.find("expected a vertex index below 8") != std::string::npos)
            << face << ": " << message;
    }
    // A face may run over several lines, as OpenMesh reads it; the cube stays whole.
    EXPECT_EQ(readMesh(write("split.off", std::string(cube).replace(cube.find("\n4 ") + 2, 1, "\n"))).triangles.size(),
              12u);
    std::string shortVertex = cube;
    shortVertex.replace(shortVertex.find("1 1 0"), 5, "1 1 zero");
    const std::string vertexMessage = messageOf(write("vertex.off", shortVertex));
    EXPECT_NE(vertexMessage.find("vertex.off: line 5: expected a number (vertex 2 of 8)"), std::string::npos)
        << vertexMessage;
    // '#' comments are not read by OpenMesh: counts after one are refused, not read as garbage.
    std::string comment = cube;
    comment.insert(comment.find('\n') + 1, "# a comment\n");
    EXPECT_NE(messageOf(write("comment.off", comment)).find("comment.off: line 2: expected an OFF header"),
              std::string::npos);
}


// OpenMesh's PLY header parser loops forever on a header cut short and
// crashes on a property before any element (found by fuzz_mesh_ply): the
// header is checked against PLY's grammar first, by line.
TEST_F(MeshReaderTest, MalformedPlyHeadersAreRefusedWithTheirLine) {
    const std::string ply = cubePly();
    const std::string cut = messageOf(write("cut_header.ply", ply.substr(0, ply.find("element face"))));
    EXPECT_NE(cut.find("cut_header.ply: expected a PLY header ending in an end_header line"), std::string::npos) << cut;

    std::string mangled = ply;
    mangled.replace(mangled.find("element vertex"), 7, std::string("el\x01\0ement", 9));
    const std::string crash = messageOf(write("mangled.ply", mangled));
    EXPECT_NE(crash.find("mangled.ply: line 3"), std::string::npos) << crash;

    std::string orphan = ply;
    orphan.insert(orphan.find("element vertex"), "property float w\n");
    EXPECT_NE(messageOf(write("orphan.ply", orphan)).find("an element line before the first property"),
              std::string::npos);
    std::string unknownType = ply;
    unknownType.replace(unknownType.find("float x"), 5, "quad ");
    EXPECT_NE(messageOf(write("type.ply", unknownType)).find("type.ply: line 4"), std::string::npos);
}

// An ASCII STL without its endsolid line was cut short, even where every
// facet before the cut is whole.
TEST_F(MeshReaderTest, AsciiStlWithoutEndsolidIsTruncated) {
    std::ostringstream stl;
    stl << "solid cube\n";
    for (const auto& q : kCubeQuads)
        for (const auto& t : {std::array<int, 3>{q[0], q[1], q[2]}, std::array<int, 3>{q[0], q[2], q[3]}}) {
            stl << "facet normal 0 0 0\n outer loop\n";
            for (int c : t)
                stl << "  vertex " << kCubeVertices[c].x << " " << kCubeVertices[c].y << " " << kCubeVertices[c].z << "\n";
            stl << " endloop\nendfacet\n";
        }
    EXPECT_EQ(readMesh(write("whole.stl", stl.str() + "endsolid cube\n")).triangles.size(), 12u);
    const std::string message = messageOf(write("no_end.stl", stl.str()));
    EXPECT_NE(message.find("no_end.stl: expected an ASCII STL file ending in an endsolid line"), std::string::npos)
        << message;
}

}  // namespace
}  // namespace eikon::io
