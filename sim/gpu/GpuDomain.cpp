#include "sim/gpu/GpuDomain.h"

#include "sim/gpu/GpuField.h"

#include <cstdint>
#include <vector>

namespace eikon::sim::gpu {

gl::Buffer solidCellFlags(const FluidDomain& domain) {
    const std::vector<std::uint32_t> flags(domain.solid.begin(), domain.solid.end());
    return gl::Buffer(flags.size() * sizeof(std::uint32_t), flags.data(), GL_DYNAMIC_STORAGE_BIT,
                      solverResource("solid cells", domain.cells));
}

GLuint openFaceBits(const FluidDomain& domain) {
    GLuint bits = 0;
    const std::array<bool, 6> open = domain.openFaces();
    for (int face = 0; face < 6; ++face)
        if (open[face]) bits |= 1u << face;
    return bits;
}

}  // namespace eikon::sim::gpu
