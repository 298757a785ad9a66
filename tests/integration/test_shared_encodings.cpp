// Small constants and encodings that C++ writes and GLSL reads are typed
// once, in files of shaders/common compiled both as GLSL and as C++
// (cpp_shim.h): the seven-point operator's cell flags
// (common/stencil_flags.glsl) and the caustic maps' sheets
// (common/caustic_sheets.glsl). A probe shader reads flags the C++ side
// encoded for every coupled set and diagonal class, encodes them again
// itself, and reports the constants as GLSL sees them.
#include "gl/GlObjects.h"
#include "gl/ShaderLibrary.h"
#include "shaders/common/cpp_shim.h"
#include "sim/fluid/StencilOperator.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <glm/vec4.hpp>

#include <cstddef>
#include <vector>

namespace eikon {
namespace {

using sim::SevenPointOperator;

constexpr const char* kEncodingProbe = R"(
layout(local_size_x = 64) in;
#include "common/stencil_flags.glsl"
#include "common/caustic_sheets.glsl"
// Per case in: (coupled, diagonal class, the flags C++ encoded, 0);
// out: (coupledBits, diagonalClass, isUnknown, stencilFlags(coupled, class)).
// After the cases: (kCausticSheets, kNotUnknown, kCoupledBits, 0).
layout(std430, binding = 0) buffer Cases { uvec4 cases[]; };
uniform uint case_count;
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i == case_count) cases[i] = uvec4(uint(kCausticSheets), kNotUnknown, kCoupledBits, 0u);
    if (i >= case_count) return;
    uvec4 c = cases[i];
    cases[i] = uvec4(coupledBits(c.z), diagonalClass(c.z), isUnknown(c.z) ? 1u : 0u, stencilFlags(c.x, c.y));
}
)";

TEST(GpuContract, StencilFlagsAndCausticSheetsReadTheSameOnBothSides) {
    test::glContext();
    // Every set of coupled faces with every diagonal class: the classes
    // are sets of faces too, and kNotUnknown marks a cell outside the system.
    std::vector<glm::uvec4> cases;
    for (unsigned coupled = 0; coupled <= SevenPointOperator::kAllCoupled; ++coupled)
        for (unsigned diagonalClass = 0; diagonalClass <= SevenPointOperator::kNotUnknown; ++diagonalClass)
            cases.emplace_back(coupled, diagonalClass, shader::stencilFlags(coupled, diagonalClass), 0u);
    const auto count = static_cast<unsigned>(cases.size());
    cases.emplace_back(0u);
    gl::Buffer buffer(cases.size() * sizeof(glm::uvec4), cases.data());
    const gl::Program probe = gl::compileComputeProgramFromSource("encoding_probe.comp", kEncodingProbe);
    buffer.bindStorage(0);
    probe.use();
    glUniform1ui(probe.uniform("case_count"), count);
    probe.dispatchCovering(cases.size());
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    const std::vector<glm::uvec4> gpu = buffer.downloadAll<glm::uvec4>();

    // The documented layout: bits 0–5 coupled, 8–14 the class.
    for (unsigned i = 0; i < count; ++i) {
        const unsigned coupled = cases[i].x, diagonalClass = cases[i].y;
        ASSERT_EQ(cases[i].z, coupled | (diagonalClass << 8)) << "C++ encoding of case " << i;
        ASSERT_EQ(gpu[i].x, coupled) << "GLSL coupledBits of case " << i;
        ASSERT_EQ(gpu[i].y, diagonalClass) << "GLSL diagonalClass of case " << i;
        ASSERT_EQ(gpu[i].z, diagonalClass != SevenPointOperator::kNotUnknown ? 1u : 0u) << "GLSL isUnknown, case " << i;
        ASSERT_EQ(gpu[i].w, cases[i].z) << "GLSL stencilFlags of case " << i;
    }
    EXPECT_EQ(gpu[count].x, static_cast<unsigned>(shader::kCausticSheets));
    EXPECT_EQ(gpu[count].x, 2u) << "a refracted and a reflected sheet";
    EXPECT_EQ(gpu[count].y, unsigned{SevenPointOperator::kNotUnknown});
    EXPECT_EQ(gpu[count].z, unsigned{SevenPointOperator::kAllCoupled});
}

}  // namespace
}  // namespace eikon
