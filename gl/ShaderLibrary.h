// Compute (and raster) programs from shaders/, with `#include "common/x.glsl"` resolved
// (each file once) and `#line` markers so compiler messages name the real
// file and line. Every program starts with `#version 450 core`, the
// extensions eikon relies on, caller-supplied #defines, `const int`
// declarations of the GPU contract's binding points, texture and image units
// and power-tally indices (bridge/layout/GpuLayouts.h: shaders name them,
// never their numbers), and shaders/common/glsl_prelude.glsl (the GLSL side
// of the C++/GLSL shim).
#pragma once

#include "gl/GlObjects.h"

#include <map>
#include <string>
#include <string_view>

namespace eikon::gl {

using ShaderDefines = std::map<std::string, std::string>;

// The full source text handed to the compiler, and the file of each
// source-string number used in its #line markers (0: the lines before the
// first marker). File k's lines are numbered from k·100000 on, so that a
// message that lost its source-string number still names its file.
struct ResolvedShader {
    std::string text;
    std::map<int, std::string> files;
};

ResolvedShader resolveShader(const std::string& name, const ShaderDefines& defines = {});

// Compiles and links a compute program; throws std::runtime_error with the
// compiler log (file names restored) on failure. The program carries `name`
// for its errors (Program::uniform).
Program compileComputeProgram(const std::string& name, const ShaderDefines& defines = {});

// A vertex and a fragment shader linked into one raster program (the
// image-space passes draw surfaces with the raster pipeline).
Program compileRasterProgram(const std::string& vertexName, const std::string& fragmentName,
                             const ShaderDefines& defines = {});

// The same for source text that is not embedded (tests' probe shaders),
// called `name` in messages; its includes resolve against shaders/ as usual.
Program compileComputeProgramFromSource(const std::string& name, std::string_view text,
                                        const ShaderDefines& defines = {});

}  // namespace eikon::gl
