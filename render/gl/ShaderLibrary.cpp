#include "render/gl/ShaderLibrary.h"

#include "render/gl/EmbeddedShaders.h"

#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace eikon::gl {

namespace {

std::string_view sourceOf(const std::string& name) {
    const auto& shaders = embeddedShaders();
    const auto found = shaders.find(name);
    if (found == shaders.end()) throw std::runtime_error("no shader named '" + name + "' is embedded");
    return found->second;
}

class Resolver {
public:
    ResolvedShader result;

    void append(const std::string& name) {
        if (!included_.insert(name).second) return;
        const int fileNumber = static_cast<int>(result.files.size());
        result.files[fileNumber] = name;
        result.text += "#line 1 " + std::to_string(fileNumber) + "\n";
        static const std::regex includeLine(R"re(^\s*#\s*include\s+"([^"]+)"\s*$)re");
        std::istringstream lines{std::string(sourceOf(name))};
        std::string line;
        int lineNumber = 0;
        while (std::getline(lines, line)) {
            ++lineNumber;
            std::smatch match;
            if (std::regex_match(line, match, includeLine)) {
                append(match[1].str());
                result.text += "#line " + std::to_string(lineNumber + 1) + " " + std::to_string(fileNumber) + "\n";
            } else {
                result.text += line + "\n";
            }
        }
    }

private:
    std::set<std::string> included_;
};

// Mesa and NVIDIA print "N:LINE(COL): ..." or "N(LINE) : ..."; put the
// file name where the source-string number is.
std::string withFileNames(const std::string& log, const std::map<int, std::string>& files) {
    static const std::regex location(R"((^|\n)(\d+)([:(]))");
    std::string out;
    auto begin = std::sregex_iterator(log.begin(), log.end(), location);
    std::size_t last = 0;
    for (auto it = begin; it != std::sregex_iterator(); ++it) {
        const auto& match = *it;
        out += log.substr(last, static_cast<std::size_t>(match.position(0)) - last);
        const auto file = files.find(std::stoi(match[2].str()));
        out += match[1].str() + (file != files.end() ? file->second : match[2].str()) + match[3].str();
        last = static_cast<std::size_t>(match.position(0) + match.length(0));
    }
    return out + log.substr(last);
}

}  // namespace

ResolvedShader resolveShader(const std::string& name, const ShaderDefines& defines) {
    Resolver resolver;
    resolver.result.text =
        "#version 450 core\n"
        "#extension GL_NV_shader_atomic_float : require\n";
    for (const auto& [key, value] : defines) resolver.result.text += "#define " + key + " " + value + "\n";
    resolver.append("common/glsl_prelude.glsl");
    resolver.append(name);
    return resolver.result;
}

Program compileComputeProgram(const std::string& name, const ShaderDefines& defines) {
    const ResolvedShader shader = resolveShader(name, defines);
    const GLuint stage = glCreateShader(GL_COMPUTE_SHADER);
    const char* text = shader.text.c_str();
    glShaderSource(stage, 1, &text, nullptr);
    glCompileShader(stage);
    auto logOf = [](GLuint object, bool isProgram) {
        GLint length = 0;
        isProgram ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length)
                  : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
        std::vector<char> log(static_cast<std::size_t>(length) + 1, '\0');
        isProgram ? glGetProgramInfoLog(object, length, nullptr, log.data())
                  : glGetShaderInfoLog(object, length, nullptr, log.data());
        return std::string(log.data());
    };
    GLint compiled = GL_FALSE;
    glGetShaderiv(stage, GL_COMPILE_STATUS, &compiled);
    if (!compiled) {
        const std::string log = logOf(stage, false);
        glDeleteShader(stage);
        throw std::runtime_error("compiling shader " + name + ":\n" + withFileNames(log, shader.files));
    }
    Program program(glCreateProgram());
    glAttachShader(program.id(), stage);
    glLinkProgram(program.id());
    glDeleteShader(stage);
    GLint linked = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &linked);
    if (!linked) throw std::runtime_error("linking shader " + name + ":\n" + logOf(program.id(), true));
    return program;
}

}  // namespace eikon::gl
