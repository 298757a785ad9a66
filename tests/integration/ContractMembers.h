// The GPU structs' members as the C++ side lays them out (offsetof, sizeof),
// from bridge/layout/GpuLayouts.h's member lists, and the lookup of a block
// member OpenGL names ("CameraBlock.position", "receivers[3].origin",
// "patches[0].corners[2].exit") in them: test_gpu_contract.cpp holds every
// member GL reports to the C++ offset and the list's GLSL type, and every
// member of a list to being reported.
#pragma once

#include "bridge/layout/GpuLayouts.h"

#include <cstddef>
#include <map>
#include <optional>
#include <set>
#include <string>

namespace eikon::test {

struct ContractMember {
    std::string glslType;
    std::size_t offset;  // in the C++ struct
    std::size_t count;   // array length; 0: not an array
    std::size_t stride;  // of an array's elements in the C++ struct
};

struct ContractStruct {
    std::size_t bytes;  // sizeof the C++ struct
    std::map<std::string, ContractMember> members;  // by GLSL name
};

inline constexpr std::size_t strideOf(std::size_t bytes, std::size_t count) { return count > 0 ? bytes / count : 0; }

// Every struct of EIKON_LAYOUT_STRUCTS by its C++ name.
inline const std::map<std::string, ContractStruct>& contractStructs() {
#define EIKON_TEST_MEMBER(cppType, cppName, glslType, glslName, count) \
    {#glslName, ContractMember{#glslType, offsetof(Struct, cppName), count, strideOf(sizeof(cppType), count)}},
#define EIKON_TEST_STRUCT(name, list)                                    \
    {#name, [] {                                                         \
         using namespace layout;                                         \
         using Struct = layout::name;                                    \
         return ContractStruct{sizeof(Struct), {list(EIKON_TEST_MEMBER)}}; \
     }()},
    static const std::map<std::string, ContractStruct> structs = {EIKON_LAYOUT_STRUCTS(EIKON_TEST_STRUCT)};
#undef EIKON_TEST_STRUCT
#undef EIKON_TEST_MEMBER
    return structs;
}

// GLSL names of structs that are members of other structs.
inline std::string nestedStructName(const std::string& glslType) {
    return glslType == "Corner" ? "GpuWavefrontCorner" : "";
}

// How a block holds its struct: as its body (array empty), or as its one
// member, an array of the struct named `array`.
struct StructuredBlock {
    std::string structName;
    std::string array;
};

struct ResolvedMember {
    std::size_t offset;
    const ContractMember* member;
};

// The C++ offset and the list's row of the block member GL calls `path`
// (its block name already stripped); nullopt where a name in it is in no
// list. `seen` collects "Struct.member" for each member the path passes.
inline std::optional<ResolvedMember> resolveMember(const StructuredBlock& block, std::string path,
                                                   std::set<std::string>& seen) {
    std::size_t offset = 0;
    const auto index = [&](std::size_t& at) {
        const std::size_t close = path.find(']', at);
        const std::size_t value = std::stoul(path.substr(at + 1, close - at - 1));
        at = close + 1;
        return value;
    };
    std::size_t at = 0;
    if (!block.array.empty()) {
        if (path.rfind(block.array + "[", 0) != 0) return std::nullopt;
        at = block.array.size();
        offset += index(at) * contractStructs().at(block.structName).bytes;
        if (at >= path.size() || path[at] != '.') return std::nullopt;
        ++at;
    }
    std::string structName = block.structName;
    while (true) {
        const ContractStruct& rows = contractStructs().at(structName);
        const std::size_t end = path.find_first_of("[.", at);
        const std::string name = path.substr(at, end == std::string::npos ? std::string::npos : end - at);
        const auto row = rows.members.find(name);
        if (row == rows.members.end()) return std::nullopt;
        seen.insert(structName + "." + name);
        offset += row->second.offset;
        at = end;
        if (at != std::string::npos && path[at] == '[') offset += index(at) * row->second.stride;
        if (at == std::string::npos || at >= path.size()) return ResolvedMember{offset, &row->second};
        if (path[at] != '.') return std::nullopt;
        structName = nestedStructName(row->second.glslType);
        if (structName.empty()) return std::nullopt;
        ++at;
    }
}

}  // namespace eikon::test
