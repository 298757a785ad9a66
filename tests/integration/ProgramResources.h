#pragma once
// Reading a linked program's resources back from OpenGL (GL 4.5 §7.3.1,
// program interface queries): names, properties, a block's member
// variables, the bytes of a member's basic type, and a GLSL type's GL enum. The GPU contract test
// checks what these report against bridge/layout/GpuLayouts.h.
#include <epoxy/gl.h>

#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace eikon::test {

inline std::string resourceName(GLuint program, GLenum interface, GLuint index) {
    GLint length = 0;
    const GLenum property = GL_NAME_LENGTH;
    glGetProgramResourceiv(program, interface, index, 1, &property, 1, nullptr, &length);
    std::string name(static_cast<std::size_t>(length), '\0');
    glGetProgramResourceName(program, interface, index, length, nullptr, name.data());
    name.resize(name.find('\0'));
    return name;
}

inline GLint resourceProperty(GLuint program, GLenum interface, GLuint index, GLenum property) {
    GLint value = 0;
    glGetProgramResourceiv(program, interface, index, 1, &property, 1, nullptr, &value);
    return value;
}

inline GLuint activeResources(GLuint program, GLenum interface) {
    GLint count = 0;
    glGetProgramInterfaceiv(program, interface, GL_ACTIVE_RESOURCES, &count);
    return static_cast<GLuint>(count);
}

inline std::vector<GLint> activeVariables(GLuint program, GLenum interface, GLuint block) {
    const GLint count = resourceProperty(program, interface, block, GL_NUM_ACTIVE_VARIABLES);
    std::vector<GLint> members(static_cast<std::size_t>(count));
    const GLenum property = GL_ACTIVE_VARIABLES;
    glGetProgramResourceiv(program, interface, block, 1, &property, count, nullptr, members.data());
    return members;
}

// Bytes of one value of a block member's basic type.
inline std::size_t typeBytes(GLenum type) {
    switch (type) {
        case GL_FLOAT: case GL_INT: case GL_UNSIGNED_INT: return 4;
        case GL_FLOAT_VEC2: case GL_INT_VEC2: case GL_UNSIGNED_INT_VEC2: return 8;
        case GL_FLOAT_VEC3: case GL_INT_VEC3: case GL_UNSIGNED_INT_VEC3: return 12;
        case GL_FLOAT_VEC4: case GL_INT_VEC4: case GL_UNSIGNED_INT_VEC4: return 16;
        default: throw std::runtime_error("a block member has GL type " + std::to_string(type) + ", unknown here");
    }
}

// The GL type of a GLSL type name as bridge/layout/GpuLayouts.h's member lists write them.
inline GLenum glTypeOf(const std::string& glslType) {
    static const std::map<std::string, GLenum> types = {
        {"uint", GL_UNSIGNED_INT}, {"vec4", GL_FLOAT_VEC4}, {"ivec4", GL_INT_VEC4}, {"uvec4", GL_UNSIGNED_INT_VEC4}};
    const auto type = types.find(glslType);
    if (type == types.end()) throw std::runtime_error("GLSL type " + glslType + " is not known here");
    return type->second;
}

}  // namespace eikon::test
