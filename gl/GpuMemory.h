// GPU memory as eikon's GL objects take it. Every texture and buffer
// reserves its bytes before it is created (GlObjects.h): the reservation is
// refused, with the size asked, the bytes already held and the limit, where
// the context's memory cannot hold it — the GPU memory still free when the
// context was made (GL_NVX_gpu_memory_info, GL_ATI_meminfo), or for a
// renderer on the CPU the machine's memory limit (bridge/core/MemoryLimit.h:
// its memory and swap, which Linux would otherwise overcommit until the
// process is killed). EIKON_MEMORY_LIMIT_MB lowers either. A 3D texture
// is also asked of the driver first by a proxy texture, and a creation the
// driver answers with GL_OUT_OF_MEMORY is refused the same way.
//
// Each object names the scene key that sized it ("grid.resolution"), so
// that `eikon run` can refuse the scene at that key before it writes a file.
#pragma once

#include "bridge/core/MemoryLimit.h"

#include <cstdint>
#include <stdexcept>
#include <string>

namespace eikon::gl {

class GpuMemoryError : public std::runtime_error {
public:
    GpuMemoryError(std::string keyPath, std::string resource, std::uint64_t bytes, std::string limit);
    const std::string& keyPath() const { return keyPath_; }  // the scene key that sized it
    const std::string& resource() const { return resource_; }
    std::uint64_t bytes() const { return bytes_; }
    const std::string& limit() const { return limit_; }

private:
    std::string keyPath_, resource_;
    std::uint64_t bytes_;
    std::string limit_;
};

// What a GL object is for, in a scene's words: the key that sized it and a
// description ("the index gradient, 384×384×384 RGBA32F").
struct GpuResource {
    std::string keyPath = "the scene";
    std::string description = "a GPU buffer";
};
// One of the textures or buffers with a value per cell of the field grid.
GpuResource gridResource(const std::string& what, int cellsX, int cellsY, int cellsZ);

// The memory the current context may take; 0: unknown (no limit is applied).
using GpuMemoryLimit = MemoryLimit;
// Reads the limit of the current context (called once it is made current).
GpuMemoryLimit queryGpuMemoryLimit(const std::string& renderer, bool rendersOnCpu);
void setGpuMemoryLimit(const GpuMemoryLimit& limit);
std::uint64_t gpuBytesHeld();

// Bytes held by one GL object from before its creation until it is deleted.
class GpuReservation {
public:
    GpuReservation() = default;
    // Throws GpuMemoryError when `bytes` more would pass the limit.
    GpuReservation(const GpuResource& resource, std::uint64_t bytes);
    ~GpuReservation();
    GpuReservation(GpuReservation&& other) noexcept;
    GpuReservation& operator=(GpuReservation&& other) noexcept;
    GpuReservation(const GpuReservation&) = delete;
    GpuReservation& operator=(const GpuReservation&) = delete;

private:
    std::uint64_t bytes_ = 0;
};

// After a glTextureStorage*/glNamedBufferStorage call: GL_OUT_OF_MEMORY
// becomes a GpuMemoryError naming the resource; another GL error, a
// std::runtime_error.
void expectCreated(const GpuResource& resource, std::uint64_t bytes);

}  // namespace eikon::gl
