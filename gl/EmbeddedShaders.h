// The GLSL sources of shaders/, compiled into the binary at build time
// (cmake/EmbedShaders.cmake), keyed by their path below shaders/, and the
// named constants and struct bodies of the GPU contract that every program
// declares.
#pragma once

#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace eikon::gl {

const std::map<std::string, std::string_view>& embeddedShaders();

struct ShaderConstant {
    const char* name;
    unsigned value;
};

// Every binding point, texture and image unit and power-tally index of
// bridge/layout/GpuLayouts.h (EIKON_LAYOUT_SHADER_CONSTANTS), by name. The
// generated file defines it: gl sees no bridge/layout
// (cmake/CheckLayering.cmake), eikon_render as a whole does.
std::span<const ShaderConstant> layoutConstants();

// One member of a GPU struct as GLSL declares it: `type name;`, or
// `type name[count];` where count > 0.
struct ShaderMember {
    std::string_view type;
    std::string_view name;
    std::size_t count;
};

// A GPU struct's member list, named as its X-macro in
// bridge/layout/GpuLayouts.h (EIKON_LAYOUT_STRUCTS); the shader library
// declares it as a GLSL macro of that name, which shaders write as the body
// of the block or struct.
struct ShaderStruct {
    const char* name;
    std::vector<ShaderMember> members;
};

std::span<const ShaderStruct> layoutStructs();

}  // namespace eikon::gl
