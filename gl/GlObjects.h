// RAII owners for OpenGL objects: each deletes its name on destruction and
// moves but never copies. Uses direct state access (OpenGL 4.5) throughout.
#pragma once

#include "gl/GpuMemory.h"

#include <epoxy/gl.h>

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace eikon::gl {

// Owns one GL name; Deleter is a function that deletes one name.
template <void (*Deleter)(GLuint)>
class GlName {
public:
    GlName() = default;
    explicit GlName(GLuint id) : id_(id) {}
    ~GlName() { reset(); }
    GlName(GlName&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    GlName& operator=(GlName&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
        }
        return *this;
    }
    GlName(const GlName&) = delete;
    GlName& operator=(const GlName&) = delete;

    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }

private:
    void reset() {
        if (id_ != 0) Deleter(id_);
        id_ = 0;
    }
    GLuint id_ = 0;
};

void deleteBuffer(GLuint id);
void deleteTexture(GLuint id);
void deleteProgram(GLuint id);

// An immutable-storage buffer (glNamedBufferStorage). Its bytes are
// reserved as `resource` (GpuMemory.h): GpuMemoryError where they do not fit.
class Buffer {
public:
    Buffer() = default;
    Buffer(std::size_t bytes, const void* data = nullptr, GLbitfield flags = GL_DYNAMIC_STORAGE_BIT,
           const GpuResource& resource = {});
    Buffer(std::size_t bytes, const GpuResource& resource) : Buffer(bytes, nullptr, GL_DYNAMIC_STORAGE_BIT, resource) {}

    GLuint id() const { return name_.id(); }
    std::size_t bytes() const { return bytes_; }
    void upload(const void* data, std::size_t bytes, std::size_t offset = 0);
    void download(void* data, std::size_t bytes, std::size_t offset = 0) const;
    void clearToZero();
    // The whole of `source`, of the same size, copied on the GPU.
    void copyFrom(const Buffer& source);
    void bindStorage(GLuint binding) const { glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, id()); }
    void bindUniform(GLuint binding) const { glBindBufferBase(GL_UNIFORM_BUFFER, binding, id()); }

    // The whole buffer as values of T.
    template <typename T>
    std::vector<T> downloadAll() const {
        std::vector<T> values(bytes_ / sizeof(T));
        if (!values.empty()) download(values.data(), values.size() * sizeof(T));
        return values;
    }

    template <typename T>
    T downloadAs(std::size_t offset = 0) const {
        T value{};
        download(&value, sizeof value, offset);
        return value;
    }

private:
    GpuReservation reservation_;
    GlName<deleteBuffer> name_;
    std::size_t bytes_ = 0;
};

// A buffer's bytes read as a texture (GL_TEXTURE_BUFFER; GLSL samplerBuffer
// and texelFetch), the buffer staying what passes write. A CPU rasterizer
// fetches texels for all the lanes of a SIMD group at once, where it loads
// a storage buffer at lane-dependent offsets one lane and one component at
// a time: read-mostly arrays that many invocations index apart (receiver
// maps, caustic vertices) are read faster as textures. internalFormat:
// GL_RGB32F, GL_RGBA32F or GL_RG32UI. Passes that wrote the buffer need
// GL_TEXTURE_FETCH_BARRIER_BIT before the texels are read. Throws
// GpuMemoryError where the buffer holds more texels than the driver's
// GL_MAX_TEXTURE_BUFFER_SIZE.
class BufferTexture {
public:
    BufferTexture() = default;
    BufferTexture(const Buffer& buffer, GLenum internalFormat, const GpuResource& resource);

    GLuint id() const { return name_.id(); }
    void bindSampler(GLuint unit) const { glBindTextureUnit(unit, id()); }

private:
    GlName<deleteTexture> name_;
};

// A 3D texture with trilinear filtering and clamp-to-edge addressing, and
// optionally a mip chain of `levels` (read with texelFetch per level).
// internalFormat: GL_R32F or GL_RGBA32F. Asked of the driver by a proxy
// texture and reserved as `resource` first (GpuMemory.h).
class Texture3D {
public:
    Texture3D() = default;
    Texture3D(GLenum internalFormat, int width, int height, int depth, int levels, const GpuResource& resource);
    Texture3D(GLenum internalFormat, int width, int height, int depth, const GpuResource& resource)
        : Texture3D(internalFormat, width, height, depth, 1, resource) {}
    // The bytes of such a texture, its mip chain included.
    static std::uint64_t bytesFor(GLenum internalFormat, int width, int height, int depth, int levels = 1);

    GLuint id() const { return name_.id(); }
    void upload(GLenum format, GLenum type, const void* data);
    // Copies the texels [begin, end) from `data`, which holds the whole
    // texture (x fastest), leaving the others as they are.
    void uploadBox(GLenum format, GLenum type, const void* data, const glm::ivec3& begin, const glm::ivec3& end);
    void bindSampler(GLuint unit) const { glBindTextureUnit(unit, id()); }
    void bindImage(GLuint unit, GLenum access) const;

private:
    GpuReservation reservation_;
    GlName<deleteTexture> name_;
    GLenum internalFormat_ = 0;
    int width_ = 0, height_ = 0, depth_ = 0;
};

// A 2D RGBA32F texture for equirectangular maps: bilinear, repeating in u
// (longitude), clamped in v.
class Texture2D {
public:
    Texture2D() = default;
    Texture2D(int width, int height, const float* rgba, const GpuResource& resource);

    GLuint id() const { return name_.id(); }
    void bindSampler(GLuint unit) const { glBindTextureUnit(unit, id()); }

private:
    GpuReservation reservation_;
    GlName<deleteTexture> name_;
};

// A linked program, named in its errors after the shader it was compiled
// from (gl::compileComputeProgram). A compute program knows its work-group
// size, read from the driver at link time (GL_COMPUTE_WORK_GROUP_SIZE): the
// shader's `layout(local_size_…)` is its only statement, and dispatches take
// counts of items, not of groups.
class Program {
public:
    Program() = default;
    explicit Program(GLuint id, std::string shaderName = "(unnamed)")
        : name_(id), shaderName_(std::move(shaderName)) {}

    GLuint id() const { return name_.id(); }
    void use() const { glUseProgram(id()); }
    // The location of a uniform the program has; throws std::runtime_error
    // naming program and uniform where it has none. OpenGL answers a
    // misspelt name with −1, which glUniform* ignores: a wrong picture, not
    // an error. Compilers also drop uniforms a program never reads, so every
    // uniform a stage sets must be read in every #define variant it compiles.
    GLint uniform(const char* name) const;

    // Reads the linked compute program's work-group size from the driver;
    // called once the program links (gl::compileComputeProgram does).
    void readWorkGroupSize();
    glm::uvec3 workGroupSize() const { return workGroupSize_; }
    // The work groups that cover `count` items along each axis: ⌈count / size⌉.
    glm::uvec3 groupsCovering(std::size_t countX, std::size_t countY = 1, std::size_t countZ = 1) const;
    // Dispatches the work groups that cover `count` items along each axis.
    void dispatchCovering(std::size_t countX, std::size_t countY = 1, std::size_t countZ = 1) const;
    // Covers a 3D grid of cells.
    void dispatchOverCells(const glm::ivec3& cells) const;
    // Dispatches exactly `groups` work groups, for the passes that count
    // groups rather than items (a reduction's partials, one group a body).
    void dispatchGroups(GLuint groupsX, GLuint groupsY = 1, GLuint groupsZ = 1) const;
    // Dispatches the work groups that an earlier pass wrote into `command`
    // (x, y, z at `offset`, glDispatchComputeIndirect).
    void dispatchIndirect(const Buffer& command, GLintptr offset = 0) const;

private:
    GlName<deleteProgram> name_;
    std::string shaderName_;
    glm::uvec3 workGroupSize_{0};
};

}  // namespace eikon::gl
