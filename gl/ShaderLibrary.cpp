#include "gl/ShaderLibrary.h"

#include "gl/EmbeddedShaders.h"

#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace eikon::gl {

namespace {

std::string_view sourceOf(const std::string& name) {
    const auto& shaders = embeddedShaders();
    const auto found = shaders.find(name);
    if (found == shaders.end()) throw std::runtime_error("no shader named '" + name + "' is embedded");
    return found->second;
}

// Mesa 22 drops the source-string number from semantic errors ("0:LINE"),
// so the lines of file k are also numbered from k·kLinesPerFile: the line
// alone names the file.
constexpr int kLinesPerFile = 100000;

std::string lineMarker(int line, int fileNumber) {
    return "#line " + std::to_string(fileNumber * kLinesPerFile + line) + " " + std::to_string(fileNumber) + "\n";
}

class Resolver {
public:
    ResolvedShader result;

    // An embedded file, unless it was appended already.
    void appendFile(const std::string& name) {
        if (included_.insert(name).second) appendText(name, sourceOf(name));
    }

    // `text` as source string `name`, its includes resolved in place.
    void appendText(const std::string& name, std::string_view text) {
        const int fileNumber = static_cast<int>(result.files.size());
        result.files[fileNumber] = name;
        result.text += lineMarker(1, fileNumber);
        static const std::regex includeLine(R"re(^\s*#\s*include\s+"([^"]+)"\s*$)re");
        std::istringstream lines{std::string(text)};
        std::string line;
        int lineNumber = 0;
        while (std::getline(lines, line)) {
            ++lineNumber;
            std::smatch match;
            if (std::regex_match(line, match, includeLine)) {
                appendFile(match[1].str());
                result.text += lineMarker(lineNumber + 1, fileNumber);
            } else {
                result.text += line + "\n";
            }
        }
    }

private:
    std::set<std::string> included_;
};

// `const int kEmitters = 2;` and so on: GLSL 4.50 takes constant expressions
// in layout(binding = ...), so shaders bind by the C++ enumerators' names.
// Then each GPU struct's members as a macro of its list's name,
// `#define EIKON_GPU_GRID vec4 bounds_min; ...`, after the constants its
// array lengths may name.
std::string layoutDeclarations() {
    std::string text = "// Binding points, units and tally indices (gl/ShaderLibrary.cpp).\n";
    for (const auto& [name, value] : layoutConstants())
        text += "const int " + std::string(name) + " = " + std::to_string(value) + ";\n";
    for (const ShaderStruct& layoutStruct : layoutStructs()) {
        text += "#define " + std::string(layoutStruct.name);
        for (const ShaderMember& member : layoutStruct.members) {
            text += " " + std::string(member.type) + " " + std::string(member.name);
            if (member.count > 0) text += "[" + std::to_string(member.count) + "]";
            text += ";";
        }
        text += "\n";
    }
    return text;
}

ResolvedShader resolveSource(const std::string& name, std::string_view text, const ShaderDefines& defines) {
    Resolver resolver;
    resolver.result.files[0] = "(prologue: #version, #extension, #define)";
    resolver.result.text =
        "#version 450 core\n"
        "#extension GL_NV_shader_atomic_float : require\n";
    for (const auto& [key, value] : defines) resolver.result.text += "#define " + key + " " + value + "\n";
    // Ahead of the prelude, so every file of shaders/common may use the names.
    resolver.appendText("bridge/layout/GpuLayouts.h (generated)", layoutDeclarations());
    resolver.appendFile("common/glsl_prelude.glsl");
    resolver.appendText(name, text);
    return resolver.result;
}

// Mesa and NVIDIA print "N:LINE(COL): ..." or "N(LINE) : ..."; put the
// file name where the source-string number is and the file's own line.
std::string withFileNames(const std::string& log, const std::map<int, std::string>& files) {
    static const std::regex location(R"((^|\n)\d+([:(])(\d+))");
    std::string out;
    auto begin = std::sregex_iterator(log.begin(), log.end(), location);
    std::size_t last = 0;
    for (auto it = begin; it != std::sregex_iterator(); ++it) {
        const auto& match = *it;
        out += log.substr(last, static_cast<std::size_t>(match.position(0)) - last);
        const int line = std::stoi(match[3].str());
        const auto file = files.find(line / kLinesPerFile);
        out += match[1].str() + (file != files.end() ? file->second : "?") + match[2].str() +
               std::to_string(line % kLinesPerFile);
        last = static_cast<std::size_t>(match.position(0) + match.length(0));
    }
    return out + log.substr(last);
}

std::string logOf(GLuint object, bool isProgram) {
    GLint length = 0;
    isProgram ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length)
              : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(length) + 1, '\0');
    isProgram ? glGetProgramInfoLog(object, length, nullptr, log.data())
              : glGetShaderInfoLog(object, length, nullptr, log.data());
    return std::string(log.data());
}

GLuint compileStage(GLenum kind, const std::string& name, const ResolvedShader& shader) {
    const GLuint stage = glCreateShader(kind);
    const char* text = shader.text.c_str();
    glShaderSource(stage, 1, &text, nullptr);
    glCompileShader(stage);
    GLint compiled = GL_FALSE;
    glGetShaderiv(stage, GL_COMPILE_STATUS, &compiled);
    if (!compiled) {
        const std::string log = logOf(stage, false);
        glDeleteShader(stage);
        throw std::runtime_error("compiling shader " + name + ":\n" + withFileNames(log, shader.files));
    }
    return stage;
}

// Links the stages (each name with its resolved text) into one program named after the first.
Program linkStages(const std::vector<std::pair<GLenum, std::pair<std::string, ResolvedShader>>>& stages) {
    std::vector<GLuint> compiled;
    try {
        for (const auto& [kind, source] : stages) compiled.push_back(compileStage(kind, source.first, source.second));
    } catch (...) {
        for (GLuint stage : compiled) glDeleteShader(stage);
        throw;
    }
    const std::string& name = stages.front().second.first;
    Program program(glCreateProgram(), name);
    for (GLuint stage : compiled) glAttachShader(program.id(), stage);
    glLinkProgram(program.id());
    for (GLuint stage : compiled) glDeleteShader(stage);
    GLint linked = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &linked);
    if (!linked) throw std::runtime_error("linking shader " + name + ":\n" + logOf(program.id(), true));
    if (stages.front().first == GL_COMPUTE_SHADER) program.readWorkGroupSize();
    return program;
}

Program compileResolved(const std::string& name, const ResolvedShader& shader) {
    return linkStages({{GL_COMPUTE_SHADER, {name, shader}}});
}

}  // namespace

ResolvedShader resolveShader(const std::string& name, const ShaderDefines& defines) {
    return resolveSource(name, sourceOf(name), defines);
}

Program compileComputeProgram(const std::string& name, const ShaderDefines& defines) {
    return compileResolved(name, resolveShader(name, defines));
}

Program compileRasterProgram(const std::string& vertexName, const std::string& fragmentName,
                             const ShaderDefines& defines) {
    return linkStages({{GL_VERTEX_SHADER, {vertexName, resolveShader(vertexName, defines)}},
                       {GL_FRAGMENT_SHADER, {fragmentName, resolveShader(fragmentName, defines)}}});
}

Program compileComputeProgramFromSource(const std::string& name, std::string_view text,
                                        const ShaderDefines& defines) {
    return compileResolved(name, resolveSource(name, text, defines));
}

}  // namespace eikon::gl
