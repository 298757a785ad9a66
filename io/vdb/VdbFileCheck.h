// Structural checks of an OpenVDB file before OpenVDB reads it.
//
// Debian's OpenVDB 10.0.1 trusts the sizes it reads: a string length or a
// compressed-chunk size taken from a corrupted file becomes an allocation of
// gigabytes or a read past a buffer's end (readZipData copies −size bytes
// before it compares them with the buffer's size). These functions walk the
// same bytes the library will read — the header, file metadata and grid
// table (openvdb/io/Archive.cc, MetaMap.cc, GridDescriptor.cc), and for a
// grid to be read its metadata, transform, tree topology and leaf buffers
// (RootNode/InternalNode/LeafNode::readTopology and readBuffers,
// io/Compression.h readCompressedValues) — and check every count, size and
// offset against the file and the format, so that what OpenVDB then reads is
// bounded by the file's size. Supported: format versions 222–224 (OpenVDB
// 3.0 and later: Blender, Houdini), files with grid offsets, float and
// vec3s grids with the standard 5-4-3 tree, half-float or full, any
// compression. Every failure is an InputError naming the file and the byte
// offset, what was expected and what was found.
#pragma once

#include <glm/mat4x4.hpp>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace eikon::io {

struct VdbGridEntry {
    std::string name;        // as OpenVDB reports it (unique suffix stripped)
    std::string valueType;   // "float", "vec3s", … from the tree type "Tree_float_5_4_3"
    std::string treeType;    // as stored, without "_HalfFloat"
    bool halfFloat = false;  // values stored as 16-bit floats
    bool instance = false;   // shares another grid's tree
    std::uint64_t gridPos = 0, blockPos = 0, endPos = 0;
};

struct VdbFileLayout {
    std::vector<VdbGridEntry> grids;
};

// Checks the header, the file metadata and the table of grids.
VdbFileLayout checkVdbHeader(std::string_view bytes, const std::string& fileName);

// A grid's tree as checkVdbGrid walked it: its nodes, which OpenVDB
// allocates whole however few of their voxels are active.
struct VdbTreeSize {
    std::uint64_t leaves = 0, lowerNodes = 0, upperNodes = 0;  // 8³, 16³ and 32³ nodes
    std::size_t valueBytes = 0;  // a value in memory: 4 (float; half floats are read as float) or 12 (vec3s)
    // OpenVDB's node sizes: a leaf's values, value mask, origin and buffer
    // pointer; an internal node's table of child pointers or tile values (a
    // union of at least 8 bytes each), its two masks and origin.
    std::uint64_t memoryBytes() const;
};

// What checkVdbGrid found of one grid.
struct VdbGridCheck {
    // Its transform's map from world to index coordinates, as OpenVDB will
    // apply it when it reads the grid (index = map · (world, 1)).
    glm::dmat4 worldToIndex{1.0};
    VdbTreeSize tree;
};
// Walks one grid (float or vec3s, not an instance) from gridPos to endPos.
VdbGridCheck checkVdbGrid(std::string_view bytes, const VdbGridEntry& grid, const std::string& fileName);

}  // namespace eikon::io
