#include "io/mesh/MeshFileChecks.h"

#include "bridge/core/Error.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <optional>
#include <set>
#include <vector>
#include <sstream>

namespace eikon::io {
namespace {

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

// The least room a declared vertex and face take after the header: as text
// "0 0 0\n" and "3 0 1 2\n"; in binary PLY three 1-byte coordinates and a
// 1-byte count with three 1-byte indices.
struct ElementBytes {
    std::size_t vertex, face;
};
constexpr ElementBytes kTextElement{6, 8}, kBinaryElement{3, 4};
// A binary OFF vertex: three 32-bit floats; a face: a count and three indices.
constexpr ElementBytes kBinaryOffElement{12, 16};

// A line quoted in a message, cut to a readable length, unprintable bytes as '?'.
std::string clippedLine(std::string line) {
    if (line.size() > 60) line = line.substr(0, 60) + "…";
    for (char& c : line)
        if (static_cast<unsigned char>(c) < 32) c = '?';
    return line;
}

// The first line of a text OFF file as OpenMesh 9's reader takes it apart:
// [ST][C][N]OFF, each prefix adding per-vertex (and, for C, per-face) values.
struct TextOffKeyword {
    bool normals = false;  // N: three more numbers a vertex
    bool colours = false;  // C: a face's line ends with its colour
};

std::optional<TextOffKeyword> textOffKeyword(const std::string& bytes) {
    std::string line = bytes.substr(0, std::min(bytes.find('\n'), bytes.size()));
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
    TextOffKeyword keyword;
    std::size_t at = 0;
    if (line.compare(at, 2, "ST") == 0) at += 2;
    keyword.colours = line.compare(at, 1, "C") == 0;
    at += keyword.colours;
    keyword.normals = line.compare(at, 1, "N") == 0;
    at += keyword.normals;
    if (line.compare(at, std::string::npos, "OFF") != 0) return std::nullopt;
    return keyword;
}

// Whitespace-separated tokens of a text file, with the line each is on.
class TextTokens {
public:
    explicit TextTokens(const std::string& bytes, std::size_t start) : bytes_(bytes), at_(start) {
        line_ += static_cast<int>(std::count(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(start), '\n'));
    }
    // The next token, or nullopt at the end of the file.
    std::optional<std::string> next() {
        while (at_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[at_]))) line_ += bytes_[at_++] == '\n';
        if (at_ == bytes_.size()) return std::nullopt;
        const std::size_t start = at_;
        while (at_ < bytes_.size() && !std::isspace(static_cast<unsigned char>(bytes_[at_]))) ++at_;
        return bytes_.substr(start, at_ - start);
    }
    void skipRestOfLine() {
        while (at_ < bytes_.size() && bytes_[at_] != '\n') ++at_;
        if (at_ < bytes_.size()) ++at_, ++line_;
    }
    std::size_t at() const { return at_; }
    int line() const { return line_; }

private:
    const std::string& bytes_;
    std::size_t at_;
    int line_ = 1;
};

bool isCount(const std::string& token) {
    return !token.empty() && token.size() <= 9 && token.find_first_not_of("0123456789") == std::string::npos;
}

// OpenMesh reads the counts after the first line as 32-bit unsigned ints
// with iostreams ('#' comments are not skipped) and, past one, loops or
// allocates without bound: anything but a count below 10^9 is refused
// (found by fuzz_mesh_off).
std::optional<std::array<unsigned long long, 3>> textOffCounts(const std::string& path, const std::string& bytes,
                                                               std::size_t& dataStart) {
    if (!textOffKeyword(bytes)) return std::nullopt;
    TextTokens tokens(bytes, 0);
    tokens.skipRestOfLine();
    std::array<unsigned long long, 3> counts{};
    for (auto& count : counts) {
        const std::optional<std::string> token = tokens.next();
        if (!token || !isCount(*token))
            throw InputError(path + ": line " + std::to_string(tokens.line()),
                             "an OFF header: OFF, then vertex, face and edge counts below 10^9",
                             token ? "\"" + clippedLine(*token) + "\"" : std::string("the end of the file"));
        count = std::stoull(*token);
    }
    dataStart = tokens.at();
    return counts;
}

// Walks a text OFF's data token by token as OpenMesh 9's read_ascii does:
// per vertex three numbers (six with N), then the rest of its line; per
// face a corner count and that many indices, wherever the line breaks fall
// (with C the rest of the line is the face's colour). OpenMesh reads a
// count of "-9" as 4294967287 and pushes corners for it from a failed
// stream until 3 GiB are gone (found by fuzz_mesh_off): every count must be
// an unsigned integer of 3 or more, every corner an index below the vertex
// count, and every number the header announces present.
void checkTextOffData(const std::string& path, const std::string& bytes, std::size_t dataStart,
                      unsigned long long vertices, unsigned long long faces) {
    const TextOffKeyword keyword = *textOffKeyword(bytes);
    TextTokens tokens(bytes, dataStart);
    const auto refuse = [&](const std::string& expected, const std::optional<std::string>& found) {
        throw InputError(path + ": line " + std::to_string(tokens.line()), expected,
                         found ? "\"" + clippedLine(*found) + "\"" : std::string("the end of the file (truncated)"));
    };
    for (unsigned long long vertex = 0; vertex < vertices; ++vertex) {
        for (int value = 0; value < (keyword.normals ? 6 : 3); ++value) {
            const std::optional<std::string> token = tokens.next();
            char* end = nullptr;
            if (token) std::strtod(token->c_str(), &end);
            if (!token || end != token->c_str() + token->size())
                refuse("a number (vertex " + std::to_string(vertex) + " of " + std::to_string(vertices) + ")", token);
        }
        tokens.skipRestOfLine();
    }
    for (unsigned long long face = 0; face < faces; ++face) {
        const std::optional<std::string> count = tokens.next();
        if (!count || !isCount(*count) || std::stoull(*count) < 3)
            refuse("a corner count of 3 or more (face " + std::to_string(face) + " of " + std::to_string(faces) + ")",
                   count);
        for (unsigned long long corner = std::stoull(*count); corner > 0; --corner) {
            const std::optional<std::string> index = tokens.next();
            if (!index || !isCount(*index) || std::stoull(*index) >= vertices)
                refuse("a vertex index below " + std::to_string(vertices) + " (face " + std::to_string(face) + ")", index);
        }
        if (keyword.colours) tokens.skipRestOfLine();
    }
}

// The counts of a binary OFF ("OFF BINARY", then V F E as 32-bit integers),
// in the byte order OpenMesh 9 reads them: the machine's own, little-endian
// on every machine eikon builds for (a big-endian file reads as nonsense
// counts there, and is refused by them).
std::optional<std::array<unsigned long long, 2>> binaryOffCounts(const std::string& path, const std::string& bytes,
                                                                 std::size_t& dataStart) {
    const std::size_t newline = bytes.find('\n');
    if (newline == std::string::npos || bytes.compare(0, 10, "OFF BINARY") != 0) return std::nullopt;
    // Cut inside its counts, OpenMesh reads them from what is there (found by fuzz_mesh_off).
    if (bytes.size() < newline + 1 + 12)
        throw InputError(path, "a binary OFF header of three 32-bit counts", "the end of the file (truncated)");
    std::uint32_t counts[2] = {};
    std::memcpy(counts, bytes.data() + newline + 1, sizeof counts);
    dataStart = newline + 1 + 12;
    return std::array<unsigned long long, 2>{counts[0], counts[1]};
}

// OpenMesh reads an OFF file as binary when its first line holds "BINARY"
// anywhere; the checks here know the plain layout only (no colours, normals
// or texture coordinates), so any other binary header is refused (an
// "OFF BINARY\b" line had OpenMesh allocate for 200 million vertices;
// found by fuzz_mesh_off).
void requirePlainBinaryOffHeader(const std::string& path, const std::string& bytes) {
    std::string line = bytes.substr(0, std::min(bytes.find('\n'), bytes.size()));
    if (line.find("BINARY") == std::string::npos) return;
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (line != "OFF BINARY")
        throw InputError(path + ": line 1", "\"OFF BINARY\" (binary OFF without colours, normals or texture coordinates)",
                         "\"" + clippedLine(line) + "\"");
}

// Walks a binary OFF's faces (a 32-bit corner count, then the corners'
// indices) as OpenMesh will read them: it loops over a count read from a
// float or past the end of the file (a billion corners) without checking.
// Each count must be 3 or more and fit in the bytes left.
void checkBinaryOffFaces(const std::string& path, const std::string& bytes, std::size_t dataStart,
                         unsigned long long vertices, unsigned long long faces) {
    std::size_t at = dataStart + static_cast<std::size_t>(std::min<unsigned long long>(vertices * 12, bytes.size()));
    for (unsigned long long face = 0; face < faces; ++face) {
        std::uint32_t corners = 0;
        if (at + 4 <= bytes.size()) std::memcpy(&corners, bytes.data() + at, sizeof corners);
        if (at + 4 > bytes.size() || corners < 3 || corners > (bytes.size() - at - 4) / 4)
            throw InputError(path + ": face " + std::to_string(face),
                             "a corner count of 3 or more whose indices the file holds",
                             at + 4 > bytes.size() ? std::string("the end of the file (truncated)")
                                                   : std::to_string(corners) + " corners");
        at += 4 + 4 * static_cast<std::size_t>(corners);
    }
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
    bool binaryOff = false, textOff = false;
    if (extension == ".off") {
        requirePlainBinaryOffHeader(path, bytes);
        if (const auto counts = textOffCounts(path, bytes, dataStart)) {
            vertices = (*counts)[0];
            faces = (*counts)[1];
            textOff = true;
        } else if (const auto binary = binaryOffCounts(path, bytes, dataStart)) {
            vertices = (*binary)[0];
            faces = (*binary)[1];
            least = kBinaryOffElement;
            binaryOff = true;
        } else {
            // Neither a text nor the plain binary header: OpenMesh reads such
            // a file anyway, from unchecked counts ("OFF0B…" hung it; found by fuzz_mesh_off).
            throw InputError(path, "an OFF header (OFF and three counts, or OFF BINARY)",
                             "\"" + clippedLine(bytes.substr(0, std::min<std::size_t>(bytes.find('\n'), 60))) + "\"");
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
    if (binaryOff) checkBinaryOffFaces(path, bytes, dataStart, vertices, faces);
    if (textOff) checkTextOffData(path, bytes, dataStart, vertices, faces);
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

// OpenMesh 9's PLY header parser trusts its input: it reads lines until
// "end_header" without stopping at the end of the file (a header cut short
// loops forever), and a property before any element writes through a null
// element (a crash). The header is checked here, line by line, against the
// PLY grammar: "ply", one format line, then comments, obj_info, elements
// (name and count) and their properties (a type and name, or "list" with
// two types and a name), up to "end_header".
void checkPlyHeader(const std::string& path, const std::string& bytes) {
    static const std::set<std::string> types{"char",  "uchar",  "short",   "ushort",  "int",   "uint",
                                             "float", "double", "int8",    "uint8",   "int16", "uint16",
                                             "int32", "uint32", "float32", "float64"};
    std::istringstream lines(bytes);
    std::string line;
    bool elements = false;
    for (int number = 1; std::getline(lines, line); ++number) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        std::istringstream words(line);
        std::vector<std::string> word{std::istream_iterator<std::string>(words), {}};
        const std::string where = path + ": line " + std::to_string(number);
        const auto refuse = [&](const std::string& expected) {
            throw InputError(where, expected, "\"" + (line.size() > 60 ? line.substr(0, 60) + "…" : line) + "\"");
        };
        if (number == 1) {
            if (line != "ply") refuse("\"ply\", the magic line of a PLY file");
            continue;
        }
        if (number == 2) {
            if (word.size() != 3 || word[0] != "format" || word[2] != "1.0" ||
                (word[1] != "ascii" && word[1] != "binary_little_endian" && word[1] != "binary_big_endian"))
                refuse("a format line (\"format ascii 1.0\", binary_little_endian or binary_big_endian, version 1.0)");
            continue;
        }
        if (word.empty()) refuse("a PLY header line, not an empty one");
        if (word[0] == "comment" || word[0] == "obj_info") continue;
        if (word[0] == "end_header") {
            if (word.size() != 1) refuse("end_header alone on its line");
            return;
        }
        if (word[0] == "element") {
            // OpenMesh reads the count as a 32-bit int: a longer one fails its stream, and it loops.
            if (word.size() != 3 || word[2].find_first_not_of("0123456789") != std::string::npos || word[2].size() > 9)
                refuse("\"element NAME COUNT\" with a count below 10^9");
            elements = true;
            continue;
        }
        if (word[0] == "property") {
            if (!elements) refuse("an element line before the first property");
            const bool list = word.size() == 5 && word[1] == "list" && types.count(word[2]) && types.count(word[3]);
            if (!list && !(word.size() == 3 && types.count(word[1])))
                refuse("\"property TYPE NAME\" or \"property list TYPE TYPE NAME\" with PLY's types");
            continue;
        }
        refuse("a PLY header line (comment, obj_info, element, property or end_header)");
    }
    throw InputError(path, "a PLY header ending in an end_header line", "none (truncated, or not a PLY file)");
}

// The data of an ASCII PLY file, walked as OpenMesh reads them: a stream
// of whitespace-separated numbers, element by element, property by
// property. OpenMesh reads a list's count as an int with iostreams and loops
// on when that fails (a count of 10^62 hung it; found by fuzz_mesh_ply): each
// count must be an integer within its declared type, and the file must hold
// every number it announces. The header has passed checkPlyHeader.
void checkAsciiPlyData(const std::string& path, const std::string& bytes) {
    struct Property {
        bool list = false;
        unsigned long long countMax = 0;
    };
    struct Element {
        std::string name;
        unsigned long long count = 0;
        std::vector<Property> properties;
    };
    std::vector<Element> elements;
    std::istringstream lines(bytes);
    std::string line;
    bool ascii = false;
    int number = 0;
    while (std::getline(lines, line)) {
        ++number;
        std::istringstream words(line);
        std::vector<std::string> word{std::istream_iterator<std::string>(words), {}};
        if (word.empty()) continue;
        if (word[0] == "format") ascii = word.size() > 1 && word[1] == "ascii";
        if (word[0] == "element") elements.push_back({word[1], std::stoull(word[2]), {}});
        if (word[0] == "property" && !elements.empty()) {
            Property property;
            if (word[1] == "list") {
                property.list = true;
                const std::string& type = word[2];
                property.countMax = (type == "uchar" || type == "uint8")   ? 255
                                    : (type == "char" || type == "int8")   ? 127
                                    : (type == "ushort" || type == "uint16") ? 65535
                                    : (type == "short" || type == "int16") ? 32767
                                                                           : 2147483647;
            }
            elements.back().properties.push_back(property);
        }
        if (word[0] == "end_header") break;
    }
    if (!ascii) return;
    std::string token;
    const auto next = [&](const std::string& what, const Element& element, unsigned long long index) -> std::string {
        if (!(lines >> token)) {
            throw InputError(path, "the numbers its header announces",
                             "the end of the file in " + what + " of " + element.name + " " + std::to_string(index) +
                                 " (truncated)");
        }
        return token;
    };
    for (const Element& element : elements)
        for (unsigned long long index = 0; index < element.count; ++index)
            for (const Property& property : element.properties) {
                const std::string value = next("a value", element, index);
                if (!property.list) continue;
                if (value.empty() || value.size() > 10 || value.find_first_not_of("0123456789") != std::string::npos ||
                    std::stoull(value) > property.countMax)
                    throw InputError(path + ": " + element.name + " " + std::to_string(index),
                                     "a list count from 0 to " + std::to_string(property.countMax),
                                     "\"" + clippedLine(value) + "\"");
                for (unsigned long long entry = std::stoull(value); entry > 0; --entry) next("a list", element, index);
            }
}

// A binary STL: an 80-byte header, a 32-bit triangle count, then 50 bytes a
// triangle (normal, three corners as 32-bit floats, 2 attribute bytes) —
// the size OpenMesh tells it from ASCII by.
bool isBinaryStl(const std::string& bytes) {
    if (bytes.size() < 84) return false;
    std::uint32_t triangles = 0;
    std::memcpy(&triangles, bytes.data() + 80, sizeof triangles);
    return bytes.size() == 84 + 50ull * triangles;
}

// OpenMesh merges STL corners by position, and a NaN corner compares equal
// to some other: it vanishes instead of being refused. Every corner
// coordinate is checked here, by triangle.
void rejectNonFiniteStlCorners(const std::string& path, const std::string& bytes) {
    const std::size_t triangles = (bytes.size() - 84) / 50;
    for (std::size_t t = 0; t < triangles; ++t)
        for (int c = 3; c < 12; ++c) {  // floats 0–2 are the normal, which is not read
            float value = 0.0f;
            std::memcpy(&value, bytes.data() + 84 + 50 * t + 4 * c, sizeof value);
            if (!std::isfinite(value))
                throw InputError(path + ": triangle " + std::to_string(t), "finite corner coordinates",
                                 std::to_string(value));
        }
}

// An ASCII STL ends with "endsolid": without it the file was cut short,
// though OpenMesh reads the facets before the cut as a whole mesh.
void requireStlEnd(const std::string& path, const std::string& bytes) {
    const std::size_t last = bytes.rfind("endsolid");
    if (last == std::string::npos || bytes.find_first_not_of(" \t\r\n", bytes.find('\n', last)) != std::string::npos)
        throw InputError(path, "an ASCII STL file ending in an endsolid line", "none (truncated)");
}

}  // namespace

void checkMeshFileBytes(const std::string& path, const std::string& extension, const std::string& bytes) {
    if (extension == ".ply") checkPlyHeader(path, bytes);
    checkDeclaredCountsFit(path, extension, bytes);
    if (extension == ".ply") checkAsciiPlyData(path, bytes);
    if (extension == ".obj") checkObjFaceIndices(path, bytes);
    if (extension == ".stl" && isBinaryStl(bytes)) {
        rejectNonFiniteStlCorners(path, bytes);
        return;
    }
    if (extension == ".stl") requireStlEnd(path, bytes);
    rejectNonFiniteLiterals(path, bytes);
}

}  // namespace eikon::io
