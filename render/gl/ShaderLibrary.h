// Compute programs from shaders/, with `#include "common/x.glsl"` resolved
// (each file once) and `#line` markers so compiler messages name the real
// file and line. Every program starts with `#version 450 core`, the
// extensions eikon relies on, caller-supplied #defines, and
// shaders/common/glsl_prelude.glsl (the GLSL side of the C++/GLSL shim).
#pragma once

#include "render/gl/GlObjects.h"

#include <map>
#include <string>

namespace eikon::gl {

using ShaderDefines = std::map<std::string, std::string>;

// The full source text handed to the compiler, and the file of each
// source-string number used in its #line markers.
struct ResolvedShader {
    std::string text;
    std::map<int, std::string> files;
};

ResolvedShader resolveShader(const std::string& name, const ShaderDefines& defines = {});

// Compiles and links a compute program; throws std::runtime_error with the
// compiler log (file names restored) on failure.
Program compileComputeProgram(const std::string& name, const ShaderDefines& defines = {});

}  // namespace eikon::gl
