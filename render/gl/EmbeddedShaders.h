// The GLSL sources of shaders/, compiled into the binary at build time
// (cmake/EmbedShaders.cmake), keyed by their path below shaders/.
#pragma once

#include <map>
#include <string>
#include <string_view>

namespace eikon::gl {

const std::map<std::string, std::string_view>& embeddedShaders();

}  // namespace eikon::gl
