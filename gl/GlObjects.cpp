#include "gl/GlObjects.h"

#include "bridge/core/Error.h"

#include <algorithm>
#include <array>
#include <stdexcept>

namespace eikon::gl {

void deleteBuffer(GLuint id) { glDeleteBuffers(1, &id); }
void deleteTexture(GLuint id) { glDeleteTextures(1, &id); }
void deleteProgram(GLuint id) { glDeleteProgram(id); }

Buffer::Buffer(std::size_t bytes, const void* data, GLbitfield flags, const GpuResource& resource)
    : reservation_(resource, bytes), bytes_(bytes) {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    name_ = GlName<deleteBuffer>(id);
    // Zero-sized storage is invalid; keep one word so bindings stay legal.
    glNamedBufferStorage(id, static_cast<GLsizeiptr>(bytes > 0 ? bytes : 4), data, flags);
    expectCreated(resource, bytes);
}

void Buffer::upload(const void* data, std::size_t bytes, std::size_t offset) {
    if (offset + bytes > bytes_) throw std::out_of_range("Buffer::upload past the end");
    glNamedBufferSubData(id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
}

void Buffer::download(void* data, std::size_t bytes, std::size_t offset) const {
    if (offset + bytes > bytes_) throw std::out_of_range("Buffer::download past the end");
    glGetNamedBufferSubData(id(), static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data);
}

void Buffer::clearToZero() {
    const GLuint zero = 0;
    glClearNamedBufferData(id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

void Buffer::copyFrom(const Buffer& source) {
    EIKON_CHECK_MSG(source.bytes() == bytes_, "a buffer copied from one of its own size");
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    if (bytes_ > 0) glCopyNamedBufferSubData(source.id(), id(), 0, 0, static_cast<GLsizeiptr>(bytes_));
}

std::uint64_t Texture3D::bytesFor(GLenum internalFormat, int width, int height, int depth, int levels) {
    EIKON_CHECK(internalFormat == GL_R32F || internalFormat == GL_RGBA32F);
    const std::uint64_t texel = internalFormat == GL_R32F ? 4 : 16;
    std::uint64_t bytes = 0;
    for (int level = 0; level < levels; ++level)
        bytes += texel * std::uint64_t(std::max(1, width >> level)) * std::uint64_t(std::max(1, height >> level)) *
                 std::uint64_t(std::max(1, depth >> level));
    return bytes;
}

namespace {

// Whether the driver can make such a texture at all (OpenGL's proxy
// textures: the driver's own size and resource checks, nothing allocated).
void requireDriverAccepts(GLenum internalFormat, int width, int height, int depth, int levels,
                          const GpuResource& resource, std::uint64_t bytes) {
    GLint largest = 0;
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &largest);
    glTexStorage3D(GL_PROXY_TEXTURE_3D, levels, internalFormat, width, height, depth);
    GLint accepted = 0;
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_WIDTH, &accepted);
    expectCreated(resource, bytes);
    if (accepted == 0)
        throw GpuMemoryError(resource.keyPath, resource.description, bytes,
                             "the driver cannot create a 3D texture that large (proxy texture test; "
                             "GL_MAX_3D_TEXTURE_SIZE is " + std::to_string(largest) + ")");
}

}  // namespace

Texture3D::Texture3D(GLenum internalFormat, int width, int height, int depth, int levels, const GpuResource& resource)
    : internalFormat_(internalFormat), width_(width), height_(height), depth_(depth) {
    const std::uint64_t bytes = bytesFor(internalFormat, width, height, depth, levels);
    requireDriverAccepts(internalFormat, width, height, depth, levels, resource, bytes);
    reservation_ = GpuReservation(resource, bytes);
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_3D, 1, &id);
    name_ = GlName<deleteTexture>(id);
    glTextureStorage3D(id, levels, internalFormat, width, height, depth);
    expectCreated(resource, bytes);
    // texelFetch reaches levels > 0 only with a mipmapped minification filter.
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_NEAREST_MIPMAP_NEAREST : GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(id, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
}

void Texture3D::upload(GLenum format, GLenum type, const void* data) {
    glTextureSubImage3D(id(), 0, 0, 0, 0, width_, height_, depth_, format, type, data);
}

void Texture3D::uploadBox(GLenum format, GLenum type, const void* data, const glm::ivec3& begin,
                          const glm::ivec3& end) {
    if (end.x <= begin.x || end.y <= begin.y || end.z <= begin.z) return;
    // The unpack state says where the box lies in the whole array.
    glPixelStorei(GL_UNPACK_ROW_LENGTH, width_);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, height_);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, begin.x);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, begin.y);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, begin.z);
    glTextureSubImage3D(id(), 0, begin.x, begin.y, begin.z, end.x - begin.x, end.y - begin.y, end.z - begin.z, format,
                        type, data);
    for (GLenum parameter : {GL_UNPACK_ROW_LENGTH, GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_PIXELS, GL_UNPACK_SKIP_ROWS,
                             GL_UNPACK_SKIP_IMAGES})
        glPixelStorei(parameter, 0);
}

void Texture3D::bindImage(GLuint unit, GLenum access) const {
    glBindImageTexture(unit, id(), 0, GL_TRUE, 0, access, internalFormat_);
}

BufferTexture::BufferTexture(const Buffer& buffer, GLenum internalFormat, const GpuResource& resource) {
    const std::size_t texelBytes = internalFormat == GL_RGB32F    ? 12
                                   : internalFormat == GL_RGBA32F ? 16
                                   : internalFormat == GL_RG32UI  ? 8
                                                                  : 0;
    if (texelBytes == 0)
        throw std::invalid_argument("BufferTexture: internalFormat must be GL_RGB32F, GL_RGBA32F or GL_RG32UI");
    GLint maxTexels = 0;
    glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
    const std::uint64_t texels = buffer.bytes() / texelBytes;
    if (texels > static_cast<std::uint64_t>(maxTexels))
        throw GpuMemoryError(resource.keyPath, resource.description + " read as a texture", buffer.bytes(),
                             std::to_string(maxTexels) + " texels (GL_MAX_TEXTURE_BUFFER_SIZE)");
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_BUFFER, 1, &id);
    name_ = GlName<deleteTexture>(id);
    glTextureBuffer(id, internalFormat, buffer.id());
}

Texture2D::Texture2D(int width, int height, const float* rgba, const GpuResource& resource)
    : reservation_(resource, 16 * std::uint64_t(width) * std::uint64_t(height)) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &id);
    name_ = GlName<deleteTexture>(id);
    glTextureStorage2D(id, 1, GL_RGBA32F, width, height);
    expectCreated(resource, 16 * std::uint64_t(width) * std::uint64_t(height));
    glTextureSubImage2D(id, 0, 0, 0, width, height, GL_RGBA, GL_FLOAT, rgba);
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

GLint Program::uniform(const char* name) const {
    const GLint location = glGetUniformLocation(id(), name);
    if (location < 0)
        throw std::runtime_error("program " + shaderName_ + " has no active uniform '" + std::string(name) +
                                 "' (misspelt, or compiled out of this variant)");
    return location;
}

void Program::readWorkGroupSize() {
    GLint size[3] = {0, 0, 0};
    glGetProgramiv(id(), GL_COMPUTE_WORK_GROUP_SIZE, size);
    workGroupSize_ = glm::uvec3(static_cast<GLuint>(size[0]), static_cast<GLuint>(size[1]),
                                static_cast<GLuint>(size[2]));
}

glm::uvec3 Program::groupsCovering(std::size_t countX, std::size_t countY, std::size_t countZ) const {
    EIKON_CHECK_MSG(workGroupSize_.x > 0, shaderName_ + ": no work-group size (not a linked compute program)");
    const std::size_t counts[3] = {countX, countY, countZ};
    glm::uvec3 groups;
    // The driver's limits, read once (every context of a process is made by the same driver).
    static const std::array<GLint, 3> mostGroups = [] {
        std::array<GLint, 3> most{};
        for (GLuint axis = 0; axis < 3; ++axis) glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, axis, &most[axis]);
        return most;
    }();
    for (int axis = 0; axis < 3; ++axis) {
        const GLint most = mostGroups[static_cast<std::size_t>(axis)];
        const std::size_t local = workGroupSize_[axis];
        const std::size_t needed = (counts[axis] + local - 1) / local;
        // A stage that asks for more work groups than the driver dispatches
        // must split its work: OpenGL would refuse with GL_INVALID_VALUE.
        EIKON_CHECK_MSG(needed <= static_cast<std::size_t>(most),
                        shaderName_ + ": " + std::to_string(needed) + " work groups along axis " +
                            std::to_string(axis) + ", above GL_MAX_COMPUTE_WORK_GROUP_COUNT " + std::to_string(most));
        groups[axis] = static_cast<GLuint>(needed);
    }
    return groups;
}

void Program::dispatchCovering(std::size_t countX, std::size_t countY, std::size_t countZ) const {
    const glm::uvec3 groups = groupsCovering(countX, countY, countZ);
    use();
    glDispatchCompute(groups.x, groups.y, groups.z);
}

void Program::dispatchOverCells(const glm::ivec3& cells) const {
    dispatchCovering(static_cast<std::size_t>(cells.x), static_cast<std::size_t>(cells.y),
                     static_cast<std::size_t>(cells.z));
}

void Program::dispatchGroups(GLuint groupsX, GLuint groupsY, GLuint groupsZ) const {
    use();
    glDispatchCompute(groupsX, groupsY, groupsZ);
}

void Program::dispatchIndirect(const Buffer& command, GLintptr offset) const {
    use();
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, command.id());
    glDispatchComputeIndirect(offset);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
}

}  // namespace eikon::gl
