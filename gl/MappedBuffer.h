// Persistently mapped buffers and fences (OpenGL 4.4 buffer storage, ARB
// sync objects): the host writes a buffer the GPU reads without mapping,
// copying or unmapping each frame; a fence tells when the GPU is done.
#pragma once

#include "gl/GlObjects.h"

#include <chrono>
#include <cstddef>
#include <utility>

namespace eikon::gl {

// A buffer mapped for reading and writing for its whole life, coherent: what
// the host writes is visible to commands issued afterwards without a flush.
// The storage is asked for in host memory (client storage), where the CPU
// also reads it at full speed.
class MappedBuffer {
public:
    MappedBuffer() = default;
    MappedBuffer(std::size_t bytes, const GpuResource& resource);

    GLuint id() const { return name_.id(); }
    std::size_t bytes() const { return bytes_; }
    float* floats() const { return static_cast<float*>(data_); }

private:
    GpuReservation reservation_;
    GlName<deleteBuffer> name_;
    std::size_t bytes_ = 0;
    void* data_ = nullptr;
};

// One fence sync object: inserted after the commands it guards.
class Fence {
public:
    Fence() = default;
    ~Fence() { reset(); }
    Fence(Fence&& other) noexcept : sync_(std::exchange(other.sync_, nullptr)) {}
    Fence& operator=(Fence&& other) noexcept {
        if (this != &other) {
            reset();
            sync_ = std::exchange(other.sync_, nullptr);
        }
        return *this;
    }
    Fence(const Fence&) = delete;
    Fence& operator=(const Fence&) = delete;

    // Guards the commands issued so far (replacing an earlier fence).
    void insert();
    bool signaled() const;
    // Blocks until the guarded commands completed; returns how long that
    // took (zero when they already had). A fence never inserted is complete.
    std::chrono::duration<double, std::milli> wait();
    void reset();

private:
    GLsync sync_ = nullptr;
};

}  // namespace eikon::gl
