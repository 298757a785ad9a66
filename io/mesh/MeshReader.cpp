#include "io/mesh/MeshReader.h"

#include "bridge/core/Error.h"
#include "io/files/FileBytes.h"
#include "io/mesh/MeshFileChecks.h"

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/importer/ImporterT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>

namespace eikon::io {
namespace {

using OmMesh = OpenMesh::TriMesh_ArrayKernelT<>;

std::string formatPoint(const glm::dvec3& p) {
    std::ostringstream text;
    text << "(" << p.x << ", " << p.y << ", " << p.z << ")";
    return text.str();
}

// OpenMesh's readers hand every vertex and face to an importer. This one
// keeps them exactly as the file states them (OpenMesh's own mesh would
// split non-manifold edges and drop faces with bad indices, hiding the
// defect), and remembers the counts a header declares (OFF, PLY).
class RecordingImporter : public OpenMesh::IO::ImporterT<OmMesh> {
public:
    explicit RecordingImporter(OmMesh& mesh) : ImporterT<OmMesh>(mesh) {}

    OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& p) override {
        vertices.emplace_back(p[0], p[1], p[2]);
        return ImporterT<OmMesh>::add_vertex(p);
    }
    OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d& p) override {
        vertices.emplace_back(p[0], p[1], p[2]);
        return ImporterT<OmMesh>::add_vertex(p);
    }
    OpenMesh::VertexHandle add_vertex() override {  // the PLY reader: add, then set_point
        vertices.emplace_back(0.0);
        return ImporterT<OmMesh>::add_vertex();
    }
    void set_point(OpenMesh::VertexHandle vertex, const OpenMesh::Vec3f& p) override {
        if (vertex.idx() >= 0 && static_cast<std::size_t>(vertex.idx()) < vertices.size())
            vertices[vertex.idx()] = glm::dvec3(p[0], p[1], p[2]);
        ImporterT<OmMesh>::set_point(vertex, p);
    }
    OpenMesh::FaceHandle add_face(const OpenMesh::IO::BaseImporter::VHandles& corners) override {
        std::vector<long long> face;
        for (const auto& corner : corners) face.push_back(corner.idx());
        faces.push_back(std::move(face));
        return ImporterT<OmMesh>::add_face(corners);
    }
    void reserve(unsigned int nV, unsigned int nE, unsigned int nF) override {
        declaredVertices = nV;
        declaredFaces = nF;
        ImporterT<OmMesh>::reserve(nV, nE, nF);
    }

    std::vector<glm::dvec3> vertices;
    std::vector<std::vector<long long>> faces;
    std::optional<unsigned int> declaredVertices;
    std::optional<unsigned int> declaredFaces;
};

// Silences OpenMesh's complaints on std::cerr while it reads: every defect
// it would print is reported through InputError instead.
// (Its PLY reader writes some to std::cerr directly, which is silenced too.)
class QuietOpenMesh {
public:
    QuietOpenMesh() : cerr_(std::cerr.rdbuf(nullptr)) { omerr().disable(); }
    ~QuietOpenMesh() {
        omerr().enable();
        std::cerr.rdbuf(cerr_);
    }
    QuietOpenMesh(const QuietOpenMesh&) = delete;
    QuietOpenMesh& operator=(const QuietOpenMesh&) = delete;

private:
    std::streambuf* cerr_;
};

TriangleMesh triangulate(const std::string& path, const RecordingImporter& importer) {
    TriangleMesh mesh;
    mesh.vertices = importer.vertices;
    const long long vertexCount = static_cast<long long>(mesh.vertices.size());
    for (std::size_t f = 0; f < importer.faces.size(); ++f) {
        const std::vector<long long>& face = importer.faces[f];
        const std::string where = path + ": face " + std::to_string(f);
        if (face.size() < 3)
            throw InputError(where, "at least 3 vertices", std::to_string(face.size()) + " (truncated or malformed)");
        for (long long corner : face)
            if (corner < 0 || corner >= vertexCount)
                throw InputError(where, "vertex indices below " + std::to_string(vertexCount) + " (the vertex count)",
                                 "index " + std::to_string(corner) + " (truncated or malformed)");
        for (std::size_t c = 1; c + 1 < face.size(); ++c)
            mesh.triangles.emplace_back(face[0], face[c], face[c + 1]);
    }
    return mesh;
}

}  // namespace

TriangleMesh readMesh(const std::string& path, MeshClosure closure) {
    std::error_code ignored;
    if (!std::filesystem::exists(path, ignored)) throw InputError(path, "a mesh file", "no such file");
    if (!std::filesystem::is_regular_file(path, ignored)) throw InputError(path, "a mesh file", "not a regular file");
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    if (extension != ".obj" && extension != ".ply" && extension != ".off" && extension != ".stl")
        throw InputError(path, "a mesh file ending in .obj, .ply, .off or .stl", "\"" + extension + "\"");
    const std::string bytes = readFileBytes(path, "a readable mesh file");
    if (bytes.empty()) throw InputError(path, "a mesh", "an empty file");
    checkMeshFileBytes(path, extension, bytes);

    OmMesh scratch;
    RecordingImporter importer(scratch);
    bool read = false;
    {
        QuietOpenMesh quiet;
        OpenMesh::IO::Options options;
        read = OpenMesh::IO::IOManager().read(path, importer, options);
    }
    if (!read) throw InputError(path, "a readable " + extension.substr(1) + " mesh", "a file OpenMesh cannot parse");
    if (importer.declaredVertices && importer.declaredFaces) {
        if (importer.vertices.size() != *importer.declaredVertices || importer.faces.size() != *importer.declaredFaces)
            throw InputError(path,
                             std::to_string(*importer.declaredVertices) + " vertices and " +
                                 std::to_string(*importer.declaredFaces) + " faces (as its header declares)",
                             std::to_string(importer.vertices.size()) + " vertices and " +
                                 std::to_string(importer.faces.size()) + " faces (truncated)");
    }
    for (std::size_t v = 0; v < importer.vertices.size(); ++v) {
        const glm::dvec3& p = importer.vertices[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw InputError(path + ": vertex " + std::to_string(v), "finite coordinates", formatPoint(p));
    }
    TriangleMesh mesh = triangulate(path, importer);
    if (mesh.triangles.empty()) throw InputError(path, "at least one face", "none (truncated or empty)");
    if (closure == MeshClosure::Closed) {
        const EdgeCensus census = countEdges(mesh);
        if (!census.closedManifold())
            throw InputError(path, "a closed manifold mesh (every edge shared by exactly two triangles)",
                             std::to_string(census.open) + " open and " + std::to_string(census.nonManifold) +
                                 " non-manifold edges of " + std::to_string(census.edges));
    }
    return mesh;
}

}  // namespace eikon::io
