// The GLSL sources of shaders/, compiled into the binary at build time
// (cmake/EmbedShaders.cmake), keyed by their path below shaders/, and the
// named constants of the GPU contract that every program declares.
#pragma once

#include <map>
#include <span>
#include <string>
#include <string_view>

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

}  // namespace eikon::gl
