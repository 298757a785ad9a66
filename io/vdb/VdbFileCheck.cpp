#include "io/vdb/VdbFileCheck.h"

#include "bridge/core/Error.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <openvdb/Metadata.h>

#include <blosc.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <vector>

namespace eikon::io {
namespace {

constexpr std::int64_t kVdbMagic = 0x56444220;  // "VDB " (OPENVDB_MAGIC)
constexpr std::uint32_t kMinVersion = 222;      // OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION
constexpr std::uint32_t kMaxVersion = 224;      // OPENVDB_FILE_VERSION_MULTIPASS_IO
constexpr std::uint32_t kMaxNameBytes = 65536;  // grid and metadata names, type names
constexpr std::uint32_t kCompressZip = 0x1, kCompressActiveMask = 0x2, kCompressBlosc = 0x4;
constexpr std::int32_t kMaxCoordinate = 1 << 30;  // keeps node origins + extents inside int32

// Log2 dimensions of the standard tree (Tree4<T, 5, 4, 3>): a root child
// spans 2^(5+4+3) = 4096 voxels per axis.
constexpr int kRootChildLog2 = 12;

// Byte reader over the file that fails, naming the file and offset, instead
// of reading past a limit.
class Cursor {
public:
    Cursor(std::string_view bytes, std::size_t pos, std::size_t end, const std::string& fileName)
        : bytes_(bytes), pos_(pos), end_(end), fileName_(fileName) {}

    std::size_t pos() const { return pos_; }
    std::size_t remaining() const { return end_ - pos_; }

    [[noreturn]] void fail(const std::string& expected, const std::string& found) const {
        throw InputError(fileName_ + ": byte " + std::to_string(pos_), expected, found);
    }

    template <class T>
    T read(const char* what) {
        need(sizeof(T), what);
        T value;
        std::memcpy(&value, bytes_.data() + pos_, sizeof(T));
        pos_ += sizeof(T);
        return value;
    }
    std::string_view peek(std::size_t count, const char* what) const {
        need(count, what);
        return bytes_.substr(pos_, count);
    }
    std::string_view take(std::size_t count, const char* what) {
        need(count, what);
        const std::string_view view = bytes_.substr(pos_, count);
        pos_ += count;
        return view;
    }
    void skip(std::size_t count, const char* what) { take(count, what); }
    // openvdb::readString: uint32 length, then the bytes.
    std::string string(const char* what, std::uint32_t maxBytes = kMaxNameBytes) {
        const auto length = read<std::uint32_t>(what);
        if (length > maxBytes || length > remaining())
            fail(std::string(what) + " of at most " + std::to_string(std::min<std::size_t>(maxBytes, remaining())) +
                     " bytes",
                 "a length of " + std::to_string(length));
        return std::string(take(length, what));
    }
    void expectAt(std::uint64_t position, const char* what) const {
        if (pos_ != position)
            fail(std::string(what) + " to end at byte " + std::to_string(position), "its end at " + std::to_string(pos_));
    }

private:
    void need(std::size_t count, const char* what) const {
        if (count > remaining())
            fail(std::to_string(count) + " more bytes for " + what,
                 remaining() == 0 ? std::string("the end of the data") : "only " + std::to_string(remaining()));
    }

    std::string_view bytes_;
    std::size_t pos_;
    std::size_t end_;
    const std::string& fileName_;
};

// Value sizes of the metadata types whose reader reads a fixed number of
// bytes whatever size the file states (TypedMetadata<T>::readValue).
const std::map<std::string, std::uint32_t>& fixedMetadataSizes() {
    static const std::map<std::string, std::uint32_t> sizes{
        {"bool", 1},   {"int32", 4},  {"int64", 8},  {"float", 4},  {"double", 8},  {"vec2i", 8},
        {"vec2s", 8},  {"vec2d", 16}, {"vec3i", 12}, {"vec3s", 12}, {"vec3d", 24},  {"vec4i", 16},
        {"vec4s", 16}, {"vec4d", 32}, {"mat4s", 64}, {"mat4d", 128}};
    return sizes;
}

// A blosc 1.x chunk of `chunkBytes` that must decompress to `rawBytes`:
// blosc_decompress trusts the compressed size in the chunk's 16-byte header
// (bytes 12–15) and reads that much, so it must be the chunk's own size; the
// reader sizes its buffer by the uncompressed size (bytes 4–7), which OpenVDB
// pads to 128 bytes for small inputs (BLOSC_PAD_BYTES, StreamCompression.cc).
void checkBloscHeader(Cursor& cursor, std::size_t chunkBytes, std::size_t rawBytes) {
    if (chunkBytes < 16) cursor.fail("a blosc chunk of at least 16 bytes", std::to_string(chunkBytes) + " bytes");
    const std::string_view header = cursor.peek(16, "a blosc header");
    std::uint32_t nbytes = 0, cbytes = 0;
    std::memcpy(&nbytes, header.data() + 4, 4);
    std::memcpy(&cbytes, header.data() + 12, 4);
    if (nbytes < rawBytes || nbytes > std::max<std::size_t>(rawBytes, 128) || cbytes != chunkBytes)
        cursor.fail("a blosc chunk of " + std::to_string(chunkBytes) + " bytes holding " + std::to_string(rawBytes),
                    "a header claiming " + std::to_string(cbytes) + " holding " + std::to_string(nbytes));
}

// DelayedLoadMetadata::readValue (openvdb/io/DelayedLoadMetadata.cc): a leaf
// count, the leaves' mask bytes (raw, or blosc after a nonzero size), then
// their 8-byte compressed sizes (absent after 0xFFFFFFFF, raw after 0, blosc
// otherwise), then bytes to skip up to numBytes.
void checkDelayedLoadMetadata(Cursor& cursor, std::uint32_t numBytes, std::size_t fileBytes) {
    if (numBytes == 0) return;
    const std::size_t end = cursor.pos() + numBytes;
    const auto count = cursor.read<std::uint32_t>("the delayed-load leaf count");
    if (count > fileBytes / 64)  // every leaf stores a 64-byte mask in the file
        cursor.fail("at most " + std::to_string(fileBytes / 64) + " delayed-load leaves", std::to_string(count));
    const auto maskBytes = cursor.read<std::uint32_t>("the delayed-load mask size");
    if (maskBytes > 0) {
        checkBloscHeader(cursor, maskBytes, count);
        cursor.skip(maskBytes, "the delayed-load mask");
    } else {
        cursor.skip(count, "the delayed-load mask");
    }
    const auto sizeBytes = cursor.read<std::uint32_t>("the delayed-load size table size");
    if (sizeBytes == 0xFFFFFFFFu) {
    } else if (sizeBytes > 0) {
        checkBloscHeader(cursor, sizeBytes, std::size_t{8} * count);
        cursor.skip(sizeBytes, "the delayed-load size table");
    } else {
        cursor.skip(std::size_t{8} * count, "the delayed-load size table");
    }
    if (cursor.pos() > end) cursor.fail("delayed-load metadata within its " + std::to_string(numBytes) + " bytes", "more");
    cursor.skip(end - cursor.pos(), "the rest of the delayed-load metadata");
}

// MetaMap::readMeta. Returns the value of the bool "is_saved_as_half_float",
// which is what Grid::readTopology reads half floats by (false if absent).
bool checkMetaMap(Cursor& cursor, std::size_t fileBytes) {
    bool savedAsHalf = false;
    const auto count = cursor.read<std::uint32_t>("the metadata count");
    if (count > cursor.remaining() / 12)  // each entry holds at least three 4-byte lengths
        cursor.fail("a metadata count that fits the file", std::to_string(count));
    for (std::uint32_t i = 0; i < count; ++i) {
        const std::string name = cursor.string("a metadata name");
        const std::string type = cursor.string("a metadata type name");
        const auto numBytes = cursor.read<std::uint32_t>("a metadata size");
        if (numBytes > cursor.remaining())
            cursor.fail("metadata \"" + type + "\" within the file", std::to_string(numBytes) + " bytes");
        const auto& fixed = fixedMetadataSizes();
        if (const auto it = fixed.find(type); it != fixed.end()) {
            if (numBytes != it->second)
                cursor.fail(std::to_string(it->second) + " bytes of " + type + " metadata", std::to_string(numBytes));
            if (type == "bool") {  // a byte other than 0 or 1 is not a valid bool
                const auto value = cursor.peek(1, "a bool")[0];
                if (value != 0 && value != 1) cursor.fail("a bool of 0 or 1", std::to_string(int(value)));
                if (name == "is_saved_as_half_float") savedAsHalf = value == 1;
            }
            cursor.skip(numBytes, "a metadata value");
        } else if (type == "__delayedload") {
            checkDelayedLoadMetadata(cursor, numBytes, fileBytes);
        } else if (type == "string" || !openvdb::Metadata::isRegisteredType(type)) {
            cursor.skip(numBytes, "a metadata value");  // read as numBytes bytes
        } else {
            cursor.fail("metadata of a plain type", "metadata of type \"" + type + "\"");
        }
    }
    return savedAsHalf;
}

// Transform::read: the map's type name, then its fixed-size members
// (openvdb/math/Maps.h). Returns the world-to-index map OpenVDB will apply:
// a scale map's stored inverse (which OpenVDB trusts, not recomputing it
// from the scale), an affine map's matrix inverted (it stores the row-vector
// form: world = (index, 1)·M, so its 16 doubles read column-major are Mᵀ).
glm::dmat4 checkTransform(Cursor& cursor) {
    const std::string type = cursor.string("the transform's map type");
    const auto vec3 = [&](const char* what) {
        glm::dvec3 v;
        for (int axis = 0; axis < 3; ++axis) v[axis] = cursor.read<double>(what);
        return v;
    };
    const auto scaleInverse = [&] {  // the scale, voxel size, inverse, inverse², inverse/2
        vec3("the map's scale");
        vec3("the map's voxel size");
        const glm::dvec3 inverse = vec3("the map's inverse scale");
        vec3("the map's squared inverse scale");
        vec3("the map's half inverse scale");
        return glm::scale(glm::dmat4(1.0), inverse);
    };
    if (type == "TranslationMap") return glm::translate(glm::dmat4(1.0), -vec3("the map's translation"));
    if (type == "UniformScaleMap" || type == "ScaleMap") return scaleInverse();
    if (type == "UniformScaleTranslateMap" || type == "ScaleTranslateMap") {
        const glm::dvec3 translation = vec3("the map's translation");
        return scaleInverse() * glm::translate(glm::dmat4(1.0), -translation);
    }
    if (type == "AffineMap" || type == "UnitaryMap") {
        glm::dmat4 transposed;
        for (int entry = 0; entry < 16; ++entry) transposed[entry / 4][entry % 4] = cursor.read<double>("the map's matrix");
        return glm::inverse(transposed);
    }
    cursor.fail("an affine transform map", "map type \"" + type + "\"");
}

struct TreeShape {
    std::size_t valueBytes;   // sizeof(ValueT)
    std::size_t storedBytes;  // bytes per stored value: half size when halfFloat
    bool halfFloat;
    std::uint32_t compression;
};

using Mask = std::string_view;  // a node's bitmask as stored, 64-bit words

std::size_t countOn(Mask mask) {
    std::size_t on = 0;
    for (unsigned char byte : mask) on += static_cast<std::size_t>(std::popcount(byte));
    return on;
}

bool bitOn(Mask mask, std::size_t index) {
    return (static_cast<unsigned char>(mask[index / 8]) >> (index % 8)) & 1u;
}

// A blosc chunk whose header fits (checkBloscHeader) decompresses to the
// bytes it claims, as io::bloscFromStream requires: OpenVDB throws from
// inside a grid's read otherwise, and leaks the nodes it had made (found by
// fuzz_vdb).
void checkBloscChunk(Cursor& cursor, std::string_view chunk, std::size_t rawBytes) {
    checkBloscHeader(cursor, chunk.size(), rawBytes);
    std::uint32_t claimed = 0;
    std::memcpy(&claimed, chunk.data() + 4, 4);
    // OpenVDB decompresses into the node's own buffer: a chunk claiming more
    // bytes than the node stores fails there (32 for a node of 8; found by
    // fuzz_vdb), one claiming fewer leaves values unread.
    if (claimed != rawBytes)
        cursor.fail("a blosc chunk of exactly the " + std::to_string(rawBytes) + " bytes the node stores",
                    std::to_string(claimed) + " bytes");
    std::vector<char> decompressed(std::max<std::size_t>(claimed, 1));
    const int result = blosc_decompress_ctx(chunk.data(), decompressed.data(), claimed, 1);
    if (result < 0 || static_cast<std::uint32_t>(result) != claimed)
        cursor.fail("a blosc chunk decompressing to the " + std::to_string(claimed) + " bytes its header claims",
                    result < 0 ? "blosc error " + std::to_string(result) : std::to_string(result) + " bytes");
}

// A zip chunk inflates to exactly the node's bytes, as io::unzipFromStream
// requires (zlib's uncompress, as it calls it): OpenVDB throws from inside
// a grid's read otherwise, and leaks the nodes it had made (found by fuzz_vdb).
void checkZipChunk(Cursor& cursor, std::string_view chunk, std::size_t rawBytes) {
    std::vector<Bytef> inflated(std::max<std::size_t>(rawBytes, 1));
    uLongf inflatedBytes = static_cast<uLongf>(rawBytes);
    const int result = uncompress(inflated.data(), &inflatedBytes, reinterpret_cast<const Bytef*>(chunk.data()),
                                  static_cast<uLong>(chunk.size()));
    if (result != Z_OK || inflatedBytes != rawBytes)
        cursor.fail("a zip chunk of " + std::to_string(chunk.size()) + " bytes inflating to exactly " +
                        std::to_string(rawBytes) + " bytes",
                    result == Z_OK ? std::to_string(inflatedBytes) + " bytes" : std::string("zlib error ") + zError(result));
}

// One compressed chunk (readZipData/readBloscData): an int64 size, negative
// (or zero) for raw bytes, which must then be exactly the buffer's size.
void checkChunk(Cursor& cursor, std::size_t rawBytes, bool blosc) {
    const auto size = cursor.read<std::int64_t>("a compressed-chunk size");
    if (size <= 0) {
        if (size == std::numeric_limits<std::int64_t>::min() || static_cast<std::uint64_t>(-size) != rawBytes)
            cursor.fail("an uncompressed chunk of exactly " + std::to_string(rawBytes) + " bytes",
                        std::to_string(-static_cast<double>(size)) + " bytes");
        cursor.skip(rawBytes, "an uncompressed chunk");
    } else {
        if (static_cast<std::uint64_t>(size) > cursor.remaining())
            cursor.fail("a compressed chunk within the grid", std::to_string(size) + " bytes");
        if (blosc) checkBloscChunk(cursor, cursor.peek(static_cast<std::size_t>(size), "a blosc chunk"), rawBytes);
        else checkZipChunk(cursor, cursor.peek(static_cast<std::size_t>(size), "a zip chunk"), rawBytes);
        cursor.skip(static_cast<std::size_t>(size), "a compressed chunk");
    }
}

// io::readCompressedValues for a node of `count` values with `valueMask`.
void checkCompressedValues(Cursor& cursor, const TreeShape& shape, std::size_t count, Mask valueMask) {
    const auto metadata = cursor.read<std::int8_t>("a node's compression metadata");
    if (metadata < 0 || metadata > 6) cursor.fail("node metadata 0 to 6", std::to_string(metadata));
    if (metadata == 2 || metadata == 4 || metadata == 5) cursor.skip(shape.valueBytes, "an inactive value");
    if (metadata == 5) cursor.skip(shape.valueBytes, "a second inactive value");
    if (metadata == 3 || metadata == 4 || metadata == 5) cursor.skip(count / 8, "a selection mask");
    const bool maskCompressed = shape.compression & kCompressActiveMask;
    const std::size_t stored = (maskCompressed && metadata != 6) ? countOn(valueMask) : count;
    if (shape.halfFloat && stored < 1) return;  // HalfReader reads nothing
    const std::size_t bytes = stored * shape.storedBytes;
    if (shape.compression & (kCompressBlosc | kCompressZip)) checkChunk(cursor, bytes, shape.compression & kCompressBlosc);
    else cursor.skip(bytes, "uncompressed values");
}

struct Walk {
    Cursor& cursor;
    TreeShape shape;
    std::vector<Mask> leafMasks;  // in the order readBuffers visits them
    std::uint64_t internalNodes[3] = {};  // per level (1: 16³, 2: 32³)

    // InternalNode<ChildT, Log2>::readTopology (format >= 222); level 2 is
    // the 32³ node, 1 the 16³ node, 0 a leaf (8³).
    void node(int level) {
        if (level == 0) {
            leafMasks.push_back(cursor.take(512 / 8, "a leaf's value mask"));
            return;
        }
        const std::size_t values = level == 2 ? 32768 : 4096;
        ++internalNodes[level];
        const Mask childMask = cursor.take(values / 8, "a node's child mask");
        const Mask valueMask = cursor.take(values / 8, "a node's value mask");
        checkCompressedValues(cursor, shape, values, valueMask);
        for (std::size_t i = 0; i < values; ++i)
            if (bitOn(childMask, i)) node(level - 1);
    }

    // RootNode::readTopology: background, tiles, then children, each
    // origin a multiple of 4096, in the order of the root's std::map.
    void root() {
        cursor.skip(shape.valueBytes, "the background value");
        const auto tiles = cursor.read<std::uint32_t>("the root tile count");
        const auto children = cursor.read<std::uint32_t>("the root child count");
        const std::size_t tileBytes = 12 + shape.valueBytes + 1;
        if (tiles > cursor.remaining() / tileBytes) cursor.fail("a tile count that fits the grid", std::to_string(tiles));
        if (children > cursor.remaining() / (12 + 2 * 4096))
            cursor.fail("a child count that fits the grid", std::to_string(children));
        std::set<std::array<std::int32_t, 3>> tileOrigins;
        for (std::uint32_t t = 0; t < tiles; ++t) {
            const auto origin = readOrigin("a tile origin");
            cursor.skip(shape.valueBytes, "a tile value");
            const auto active = cursor.read<std::uint8_t>("a tile's active flag");
            if (active > 1) cursor.fail("an active flag of 0 or 1", std::to_string(active));
            if (!tileOrigins.insert(origin).second) cursor.fail("distinct tile origins", "a repeated one");
        }
        std::array<std::int32_t, 3> previous{};
        for (std::uint32_t c = 0; c < children; ++c) {
            const auto origin = readOrigin("a child origin");
            for (int a = 0; a < 3; ++a)
                if (origin[a] % (1 << kRootChildLog2) != 0)
                    cursor.fail("a child origin that is a multiple of 4096", std::to_string(origin[a]));
            if ((c > 0 && !(previous < origin)) || tileOrigins.count(origin))
                cursor.fail("child origins in increasing order, apart from the tiles", "one out of order or repeated");
            previous = origin;
            node(2);
        }
    }

    std::array<std::int32_t, 3> readOrigin(const char* what) {
        std::array<std::int32_t, 3> origin{};
        for (auto& v : origin) {
            v = cursor.read<std::int32_t>(what);
            if (v < -kMaxCoordinate || v > kMaxCoordinate)
                cursor.fail("a coordinate within ±2^30", std::to_string(v));
        }
        return origin;
    }

    // LeafNode::readBuffers (format >= 222): the value mask again, then the values.
    void buffers() {
        for (const Mask mask : leafMasks) {
            const Mask again = cursor.take(512 / 8, "a leaf's buffer mask");
            if (again != mask) cursor.fail("a leaf buffer mask equal to its topology mask", "a different mask");
            checkCompressedValues(cursor, shape, 512, mask);
        }
    }
};

std::string valueTypeOf(const std::string& treeType) {
    // "Tree_float_5_4_3" → "float"
    const std::string prefix = "Tree_", suffix = "_5_4_3";
    if (treeType.size() <= prefix.size() + suffix.size() || treeType.rfind(prefix, 0) != 0 ||
        treeType.compare(treeType.size() - suffix.size(), suffix.size(), suffix) != 0)
        return "";
    return treeType.substr(prefix.size(), treeType.size() - prefix.size() - suffix.size());
}

}  // namespace

VdbFileLayout checkVdbHeader(std::string_view bytes, const std::string& fileName) {
    Cursor cursor(bytes, 0, bytes.size(), fileName);
    VdbFileLayout layout;
    const auto magic = cursor.read<std::int64_t>("the OpenVDB magic number");
    if (magic != kVdbMagic) cursor.fail("an OpenVDB file (magic number 0x56444220)", "another magic number");
    const auto version = cursor.read<std::uint32_t>("the file format version");
    if (version < kMinVersion || version > kMaxVersion)
        cursor.fail("file format version " + std::to_string(kMinVersion) + " to " + std::to_string(kMaxVersion) +
                        " (OpenVDB 3.0 or later)",
                    "version " + std::to_string(version));
    cursor.read<std::uint32_t>("the library major version");
    cursor.read<std::uint32_t>("the library minor version");
    const auto offsets = cursor.read<std::uint8_t>("the grid-offsets flag");
    if (offsets != 1) cursor.fail("a file with grid offsets (written by openvdb::io::File)", "flag " + std::to_string(offsets));
    cursor.skip(36, "the file UUID");
    checkMetaMap(cursor, bytes.size());

    const auto count = cursor.read<std::int32_t>("the grid count");
    if (count < 0 || static_cast<std::size_t>(count) > cursor.remaining() / 36)
        cursor.fail("a grid count that fits the file", std::to_string(count));
    std::size_t next = cursor.pos();
    for (std::int32_t g = 0; g < count; ++g) {
        Cursor entry(bytes, next, bytes.size(), fileName);
        VdbGridEntry grid;
        const std::string unique = entry.string("a grid name");
        grid.name = unique.substr(0, unique.find('\x1e'));  // GridDescriptor::stripSuffix
        grid.treeType = entry.string("a grid type");
        const std::string half = "_HalfFloat";
        if (grid.treeType.size() > half.size() &&
            grid.treeType.compare(grid.treeType.size() - half.size(), half.size(), half) == 0) {
            grid.halfFloat = true;
            grid.treeType.resize(grid.treeType.size() - half.size());
        }
        grid.valueType = valueTypeOf(grid.treeType);
        grid.instance = !entry.string("an instance parent name").empty();
        const auto gridPos = entry.read<std::int64_t>("a grid offset");
        const auto blockPos = entry.read<std::int64_t>("a grid's block offset");
        const auto endPos = entry.read<std::int64_t>("a grid's end offset");
        if (gridPos != static_cast<std::int64_t>(entry.pos()) || blockPos < gridPos || endPos < blockPos ||
            static_cast<std::uint64_t>(endPos) > bytes.size())
            entry.fail("grid offsets in order within the file (" + std::to_string(bytes.size()) + " bytes)",
                       std::to_string(gridPos) + ", " + std::to_string(blockPos) + ", " + std::to_string(endPos));
        grid.gridPos = static_cast<std::uint64_t>(gridPos);
        grid.blockPos = static_cast<std::uint64_t>(blockPos);
        grid.endPos = static_cast<std::uint64_t>(endPos);
        next = grid.endPos;
        for (const VdbGridEntry& other : layout.grids)
            if (other.name == grid.name) entry.fail("grids with distinct names", "\"" + grid.name + "\" twice");
        layout.grids.push_back(std::move(grid));
    }
    return layout;
}

std::uint64_t VdbTreeSize::memoryBytes() const {
    const std::uint64_t slot = std::max<std::uint64_t>(8, (valueBytes + 7) / 8 * 8);
    return leaves * (512 * valueBytes + 512 / 8 + 12 + 8) + lowerNodes * (4096 * slot + 2 * 4096 / 8 + 12) +
           upperNodes * (32768 * slot + 2 * 32768 / 8 + 12);
}

VdbGridCheck checkVdbGrid(std::string_view bytes, const VdbGridEntry& grid, const std::string& fileName) {
    EIKON_CHECK(grid.endPos <= bytes.size() && grid.gridPos <= grid.blockPos && grid.blockPos <= grid.endPos);
    Cursor cursor(bytes, grid.gridPos, grid.blockPos, fileName);
    const std::string where = "grid \"" + grid.name + "\"";
    if (grid.instance) cursor.fail(where + " with its own tree", "an instance of another grid");
    std::size_t valueBytes = 0, halfBytes = 0;
    if (grid.valueType == "float") valueBytes = 4, halfBytes = 2;
    else if (grid.valueType == "vec3s") valueBytes = 12, halfBytes = 6;
    else cursor.fail(where + " of type float or vec3s with a 5-4-3 tree", "\"" + grid.treeType + "\"");

    const auto compression = cursor.read<std::uint32_t>("the grid's compression flags");
    if (compression > (kCompressZip | kCompressActiveMask | kCompressBlosc))
        cursor.fail("compression flags of at most 7", std::to_string(compression));
    if (checkMetaMap(cursor, bytes.size()) != grid.halfFloat)
        cursor.fail(where + " whose metadata is_saved_as_half_float agrees with its type name",
                    grid.halfFloat ? "half floats by name only" : "half floats by metadata only");
    const glm::dmat4 worldToIndex = checkTransform(cursor);
    const auto bufferCount = cursor.read<std::int32_t>("the tree's buffer count");
    if (bufferCount != 1) cursor.fail("a tree with one buffer", std::to_string(bufferCount));
    Walk walk{cursor, {valueBytes, grid.halfFloat ? halfBytes : valueBytes, grid.halfFloat, compression}, {}};
    walk.root();
    cursor.expectAt(grid.blockPos, "the tree topology");

    const VdbTreeSize size{walk.leafMasks.size(), walk.internalNodes[1], walk.internalNodes[2], valueBytes};
    Cursor blocks(bytes, grid.blockPos, grid.endPos, fileName);
    Walk leaves{blocks, walk.shape, std::move(walk.leafMasks)};
    leaves.buffers();
    blocks.expectAt(grid.endPos, "the leaf buffers");
    return {worldToIndex, size};
}

}  // namespace eikon::io
