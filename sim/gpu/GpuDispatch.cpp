#include "sim/gpu/GpuDispatch.h"

#include "bridge/core/Error.h"

namespace eikon::sim::gpu {

namespace {
constexpr std::size_t kGroupsAlongX = 32768;  // under every driver's 65 535, a power of two
}

void dispatchOverEntries(const gl::Program& program, std::size_t count, unsigned localSize) {
    if (count == 0) return;
    program.use();
    const std::size_t groups = (count + localSize - 1) / localSize;
    const std::size_t x = groups < kGroupsAlongX ? groups : kGroupsAlongX;
    const std::size_t y = (groups + x - 1) / x;
    EIKON_CHECK(y <= 65535);
    glDispatchCompute(static_cast<GLuint>(x), static_cast<GLuint>(y), 1);
}

}  // namespace eikon::sim::gpu
