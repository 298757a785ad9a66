#include "io/mesh/MeshReader.h"

#include "bridge/core/Error.h"
#include "io/files/FileBytes.h"

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/importer/ImporterT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
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

// OpenMesh's text readers parse numbers with iostreams, which fail on "nan"
// and "inf" and then read zeros: such literals are found here, by line.
void rejectNonFiniteLiterals(const std::string& path, const std::string& bytes) {
    if (bytes.find('\0') != std::string::npos) return;  // binary: checked after reading
    std::istringstream lines(bytes);
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number) {
        std::istringstream tokens(line);
        std::string token;
        while (tokens >> token) {
            std::string word = token;
            std::transform(word.begin(), word.end(), word.begin(), [](unsigned char c) { return std::tolower(c); });
            if (!word.empty() && (word[0] == '+' || word[0] == '-')) word.erase(0, 1);
            if (word.rfind("nan", 0) == 0 || word.rfind("inf", 0) == 0)
                throw InputError(path + ": line " + std::to_string(number), "finite vertex coordinates",
                                 "\"" + token + "\"");
        }
    }
}

// Lines of a text OFF or ASCII PLY file after its header, blank lines and
// '#' comments left out; nullopt for other files. OpenMesh's text readers
// repeat the last values they read when a file ends early, so truncation
// shows only here: a header declaring V vertices and F faces needs V + F lines.
std::optional<std::size_t> dataLines(const std::string& extension, const std::string& bytes) {
    const bool isText = bytes.find('\0') == std::string::npos;
    if (!isText || (extension != ".off" && extension != ".ply")) return std::nullopt;
    if (extension == ".ply" && bytes.find("format ascii") == std::string::npos) return std::nullopt;
    std::istringstream lines(bytes);
    std::string line;
    std::size_t headerLines = extension == ".off" ? 2 : 0;  // "OFF" and the counts
    bool inHeader = extension == ".ply";
    std::size_t count = 0;
    while (std::getline(lines, line)) {
        const std::size_t first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        if (inHeader) {
            inHeader = line.compare(first, 10, "end_header") != 0;
        } else if (headerLines > 0) {
            --headerLines;
        } else {
            ++count;
        }
    }
    return count;
}

// The least room a declared vertex and face take after the header: as text
// "0 0 0\n" and "3 0 1 2\n"; in binary PLY three 1-byte coordinates and a
// 1-byte count with three 1-byte indices.
struct ElementBytes {
    std::size_t vertex, face;
};
constexpr ElementBytes kTextElement{6, 8}, kBinaryElement{3, 4};
// A binary OFF vertex: three 32-bit floats; a face: a count and three indices.
constexpr ElementBytes kBinaryOffElement{12, 16};

// Where the data of a text OFF file start and the counts its header
// declares ("OFF" and its variants, then V F E; '#' comments anywhere);
// nullopt for a binary OFF or a header that does not parse.
std::optional<std::array<unsigned long long, 3>> textOffCounts(const std::string& bytes, std::size_t& dataStart) {
    std::size_t at = 0;
    auto nextToken = [&]() -> std::string {
        for (;;) {
            while (at < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[at]))) ++at;
            if (at < bytes.size() && bytes[at] == '#') {
                while (at < bytes.size() && bytes[at] != '\n') ++at;
                continue;
            }
            break;
        }
        const std::size_t start = at;
        while (at < bytes.size() && !std::isspace(static_cast<unsigned char>(bytes[at]))) ++at;
        return bytes.substr(start, at - start);
    };
    const std::string keyword = nextToken();
    if (keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0) return std::nullopt;
    std::array<unsigned long long, 3> counts{};
    for (auto& count : counts) {
        const std::string token = nextToken();
        if (token == "BINARY" || token.empty() || token.find_first_not_of("0123456789") != std::string::npos)
            return std::nullopt;
        count = std::stoull(token.substr(0, 19));
    }
    dataStart = at;
    return counts;
}

// The counts of a binary OFF ("OFF BINARY", then V F E as 32-bit integers).
// Which byte order the writer used is not stated, so of the two readings
// the one that asks less of the file is kept: a valid file fits in its own
// order, and a count that is absurd in one order is large in the other too.
std::optional<std::array<unsigned long long, 2>> binaryOffCounts(const std::string& bytes, std::size_t& dataStart) {
    const std::size_t newline = bytes.find('\n');
    if (newline == std::string::npos || bytes.compare(0, newline, "OFF BINARY") != 0 ||
        bytes.size() < newline + 1 + 12)
        return std::nullopt;
    const auto word = [&](std::size_t at, bool bigEndian) {
        unsigned long long value = 0;
        for (int b = 0; b < 4; ++b) {
            const auto byte = static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(bigEndian ? b : 3 - b)]);
            value = (value << 8) | byte;
        }
        return value;
    };
    const std::size_t at = newline + 1;
    std::array<unsigned long long, 2> little{word(at, false), word(at + 4, false)};
    std::array<unsigned long long, 2> big{word(at, true), word(at + 4, true)};
    dataStart = at + 12;
    const auto need = [](const std::array<unsigned long long, 2>& c) {
        return static_cast<long double>(c[0]) * kBinaryOffElement.vertex + static_cast<long double>(c[1]) * kBinaryOffElement.face;
    };
    return need(little) <= need(big) ? little : big;
}

// The same for a PLY header: its vertex and face element counts, and whether
// its data are text.
std::optional<std::array<unsigned long long, 2>> plyCounts(const std::string& bytes, std::size_t& dataStart,
                                                           bool& text) {
    const std::size_t end = bytes.find("end_header");
    if (end == std::string::npos) return std::nullopt;
    std::istringstream header(bytes.substr(0, end));
    std::array<unsigned long long, 2> counts{};
    std::string line;
    text = false;
    while (std::getline(header, line)) {
        std::istringstream words(line);
        std::string first, second;
        unsigned long long count = 0;
        words >> first >> second;
        if (first == "format") text = second == "ascii";
        if (first == "element" && (second == "vertex" || second == "face") && words >> count)
            counts[second == "vertex" ? 0 : 1] = count;
    }
    const std::size_t newline = bytes.find('\n', end);
    dataStart = newline == std::string::npos ? bytes.size() : newline + 1;
    return counts;
}

// Counts an OFF or PLY header declares must fit in the file before any
// reader allocates for them (a header declaring 2e9 faces would have
// OpenMesh add faces past the end of the file for gigabytes).
void checkDeclaredCountsFit(const std::string& path, const std::string& extension, const std::string& bytes) {
    std::size_t dataStart = 0;
    unsigned long long vertices = 0, faces = 0;
    ElementBytes least = kTextElement;
    if (extension == ".off") {
        if (const auto counts = textOffCounts(bytes, dataStart)) {
            vertices = (*counts)[0];
            faces = (*counts)[1];
        } else if (const auto binary = binaryOffCounts(bytes, dataStart)) {
            vertices = (*binary)[0];
            faces = (*binary)[1];
            least = kBinaryOffElement;
        } else {
            return;
        }
    } else if (extension == ".ply") {
        bool text = false;
        const auto counts = plyCounts(bytes, dataStart, text);
        if (!counts) return;
        vertices = (*counts)[0];
        faces = (*counts)[1];
        if (!text) least = kBinaryElement;
    } else {
        return;
    }
    const unsigned long long room = bytes.size() - std::min(dataStart, bytes.size()) + 1;  // the last line may lack its newline
    const long double needed = static_cast<long double>(vertices) * least.vertex + static_cast<long double>(faces) * least.face;
    if (needed > static_cast<long double>(room))
        throw InputError(path,
                         "vertex and face counts its " + std::to_string(room - 1) + " bytes of data can hold (" +
                             std::to_string(least.vertex) + " bytes a vertex, " + std::to_string(least.face) +
                             " a face at least)",
                         "a header declaring " + std::to_string(vertices) + " vertices and " + std::to_string(faces) +
                             " faces (truncated, or wrong counts)");
}

// OpenMesh's OBJ reader drops a face whose vertex index does not parse as
// an int (99999999999999999999, say) or points nowhere, without a word:
// every face's vertex references are checked here first, by line. OBJ
// indices count from 1, negative ones back from the latest vertex.
void checkObjFaceIndices(const std::string& path, const std::string& bytes) {
    std::istringstream lines(bytes);
    std::string line;
    long long vertices = 0;
    for (int number = 1; std::getline(lines, line); ++number) {
        std::istringstream tokens(line);
        std::string keyword;
        tokens >> keyword;
        if (keyword == "v") ++vertices;
        if (keyword != "f") continue;
        std::string corner;
        while (tokens >> corner) {
            const std::string index = corner.substr(0, corner.find('/'));
            const bool digits = !index.empty() && index.size() <= 18 &&
                                index.find_first_not_of("0123456789", index[0] == '-' ? 1 : 0) == std::string::npos &&
                                index != "-";
            const long long value = digits ? std::stoll(index) : 0;
            if (!digits || value == 0 || value > vertices || value < -vertices)
                throw InputError(path + ": line " + std::to_string(number),
                                 "vertex indices from 1 to " + std::to_string(vertices) + " (or -1 to -" +
                                     std::to_string(vertices) + "), the vertices defined so far",
                                 "\"" + (index.size() > 40 ? index.substr(0, 40) + "…" : index) + "\"");
        }
    }
}

// Silences OpenMesh's complaints on std::cerr while it reads: every defect
// it would print is reported through InputError instead.
class QuietOpenMesh {
public:
    QuietOpenMesh() { omerr().disable(); }
    ~QuietOpenMesh() { omerr().enable(); }
    QuietOpenMesh(const QuietOpenMesh&) = delete;
    QuietOpenMesh& operator=(const QuietOpenMesh&) = delete;
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
    checkDeclaredCountsFit(path, extension, bytes);
    if (extension == ".obj") checkObjFaceIndices(path, bytes);
    rejectNonFiniteLiterals(path, bytes);

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
        const std::size_t declared = std::size_t{*importer.declaredVertices} + *importer.declaredFaces;
        const std::optional<std::size_t> lines = dataLines(extension, bytes);
        if (importer.vertices.size() != *importer.declaredVertices || importer.faces.size() != *importer.declaredFaces ||
            (lines && *lines < declared))
            throw InputError(path,
                             std::to_string(*importer.declaredVertices) + " vertices and " +
                                 std::to_string(*importer.declaredFaces) + " faces (as its header declares)",
                             lines ? std::to_string(*lines) + " vertex and face lines (truncated)"
                                   : std::to_string(importer.vertices.size()) + " vertices and " +
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
