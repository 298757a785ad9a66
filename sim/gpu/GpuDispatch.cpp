#include "sim/gpu/GpuDispatch.h"

#include "bridge/core/Error.h"

namespace eikon::sim::gpu {

namespace {
constexpr std::size_t kGroupsAlongX = 32768;  // under every driver's 65 535, a power of two
}

void dispatchOverEntries(const gl::Program& program, std::size_t count) {
    if (count == 0) return;
    const glm::uvec3 local = program.workGroupSize();
    EIKON_CHECK(local.x > 0 && local.y == 1 && local.z == 1);  // a one-dimensional pass
    const std::size_t groups = (count + local.x - 1) / local.x;
    const std::size_t x = groups < kGroupsAlongX ? groups : kGroupsAlongX;
    const std::size_t y = (groups + x - 1) / x;
    EIKON_CHECK(y <= 65535);
    program.dispatchGroups(static_cast<GLuint>(x), static_cast<GLuint>(y));
}

}  // namespace eikon::sim::gpu
