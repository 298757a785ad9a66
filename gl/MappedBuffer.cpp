#include "gl/MappedBuffer.h"

#include <stdexcept>
#include <string>

namespace eikon::gl {

MappedBuffer::MappedBuffer(std::size_t bytes, const GpuResource& resource) : reservation_(resource, bytes), bytes_(bytes) {
    constexpr GLbitfield kAccess = GL_MAP_READ_BIT | GL_MAP_WRITE_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
    GLuint id = 0;
    glCreateBuffers(1, &id);
    name_ = GlName<deleteBuffer>(id);
    glNamedBufferStorage(id, static_cast<GLsizeiptr>(bytes), nullptr, kAccess | GL_CLIENT_STORAGE_BIT);
    expectCreated(resource, bytes);
    data_ = glMapNamedBufferRange(id, 0, static_cast<GLsizeiptr>(bytes), kAccess);
    if (!data_) throw std::runtime_error("OpenGL could not map a persistent buffer of " + std::to_string(bytes) + " bytes");
}

void Fence::insert() {
    reset();
    sync_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

bool Fence::signaled() const {
    if (!sync_) return true;
    GLint status = GL_UNSIGNALED;
    glGetSynciv(sync_, GL_SYNC_STATUS, 1, nullptr, &status);
    return status == GL_SIGNALED;
}

std::chrono::duration<double, std::milli> Fence::wait() {
    const auto start = std::chrono::steady_clock::now();
    if (sync_) {
        constexpr GLuint64 kSecond = 1'000'000'000;
        GLenum status = glClientWaitSync(sync_, GL_SYNC_FLUSH_COMMANDS_BIT, kSecond);
        while (status == GL_TIMEOUT_EXPIRED) status = glClientWaitSync(sync_, 0, kSecond);
        if (status == GL_WAIT_FAILED) throw std::runtime_error("OpenGL fence wait failed");
        reset();
    }
    return std::chrono::steady_clock::now() - start;
}

void Fence::reset() {
    if (sync_) glDeleteSync(sync_);
    sync_ = nullptr;
}

}  // namespace eikon::gl
