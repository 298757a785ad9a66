#include "gl/GpuMemory.h"

#include <epoxy/gl.h>

#include <optional>
#include <utility>

namespace eikon::gl {

namespace {

GpuMemoryLimit currentLimit;
std::uint64_t held = 0;

// The GPU's own memory, lowered to EIKON_MEMORY_LIMIT_MB where that is less.
GpuMemoryLimit lowered(GpuMemoryLimit limit) {
    const std::optional<MemoryLimit> environment = memoryLimitFromEnvironment();
    return environment && environment->bytes < limit.bytes ? *environment : limit;
}

}  // namespace

GpuMemoryError::GpuMemoryError(std::string keyPath, std::string resource, std::uint64_t bytes, std::string limit)
    : std::runtime_error(keyPath + ": " + resource + " needs " + mebibytes(bytes) + "; " + limit),
      keyPath_(std::move(keyPath)), resource_(std::move(resource)), bytes_(bytes), limit_(std::move(limit)) {}

GpuMemoryLimit queryGpuMemoryLimit(const std::string& renderer, bool rendersOnCpu) {
    if (rendersOnCpu) {
        const MemoryLimit machine = machineMemoryLimit();
        if (machine.bytes) return {machine.bytes, renderer + " renders on the CPU, within " + machine.source};
    }
    if (epoxy_has_gl_extension("GL_NVX_gpu_memory_info")) {
        GLint kibibytes = 0;
        glGetIntegerv(GL_GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX, &kibibytes);
        const std::uint64_t available = std::uint64_t(kibibytes) * 1024;
        if (available)
            return lowered({available, renderer + " had " + mebibytes(available) + " free (GL_NVX_gpu_memory_info)"});
    }
    if (epoxy_has_gl_extension("GL_ATI_meminfo")) {
        GLint free[4] = {};
        glGetIntegerv(GL_TEXTURE_FREE_MEMORY_ATI, free);
        const std::uint64_t available = std::uint64_t(free[0]) * 1024;
        if (available) return lowered({available, renderer + " had " + mebibytes(available) + " free (GL_ATI_meminfo)"});
    }
    return memoryLimitFromEnvironment().value_or(GpuMemoryLimit{});
}

GpuResource gridResource(const std::string& what, int cellsX, int cellsY, int cellsZ) {
    return {"grid.resolution", what + " over " + std::to_string(cellsX) + "×" + std::to_string(cellsY) + "×" +
                                   std::to_string(cellsZ) + " cells"};
}

void setGpuMemoryLimit(const GpuMemoryLimit& limit) { currentLimit = limit; }

std::uint64_t gpuBytesHeld() { return held; }

GpuReservation::GpuReservation(const GpuResource& resource, std::uint64_t bytes) {
    if (currentLimit.bytes && held + bytes > currentLimit.bytes)
        throw GpuMemoryError(resource.keyPath, resource.description, bytes,
                             mebibytes(held) + " already held; " + currentLimit.source);
    held += bytes;
    bytes_ = bytes;
}

GpuReservation::~GpuReservation() { held -= bytes_; }

GpuReservation::GpuReservation(GpuReservation&& other) noexcept : bytes_(std::exchange(other.bytes_, 0)) {}

GpuReservation& GpuReservation::operator=(GpuReservation&& other) noexcept {
    if (this != &other) {
        held -= bytes_;
        bytes_ = std::exchange(other.bytes_, 0);
    }
    return *this;
}

void expectCreated(const GpuResource& resource, std::uint64_t bytes) {
    const GLenum error = glGetError();
    if (error == GL_OUT_OF_MEMORY)
        throw GpuMemoryError(resource.keyPath, resource.description, bytes,
                             "the driver is out of memory for it (GL_OUT_OF_MEMORY)");
    if (error != GL_NO_ERROR)
        throw std::runtime_error("OpenGL error " + std::to_string(error) + " creating " + resource.description +
                                 " (" + mebibytes(bytes) + ")");
}

}  // namespace eikon::gl
