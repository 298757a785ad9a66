// The work-group size is the shader's alone: gl::Program reads it from the
// driver at link time (GL_COMPUTE_WORK_GROUP_SIZE) and every dispatch takes
// a count of items. A probe that marks each item it is given, compiled at
// local sizes that differ only in its #defines, must mark every item of a
// count none of them divides exactly once, and none past it.
#include "gl/GlObjects.h"
#include "gl/ShaderLibrary.h"
#include "tests/integration/GlTestContext.h"

#include <gtest/gtest.h>

#include <glm/vec3.hpp>

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace eikon {
namespace {

constexpr const char* kMarkProbe = R"(
layout(local_size_x = LOCAL_X, local_size_y = LOCAL_Y, local_size_z = LOCAL_Z) in;
layout(std430, binding = 0) buffer Marks { uint marks[]; };
uniform uvec3 count;
void main() {
    uvec3 item = gl_GlobalInvocationID;
    if (any(greaterThanEqual(item, count))) return;
    atomicAdd(marks[item.x + count.x * (item.y + count.y * item.z)], 1u);
}
)";

gl::Program markProbe(const glm::uvec3& local) {
    return gl::compileComputeProgramFromSource("mark_probe.comp", kMarkProbe,
                                               {{"LOCAL_X", std::to_string(local.x)},
                                                {"LOCAL_Y", std::to_string(local.y)},
                                                {"LOCAL_Z", std::to_string(local.z)}});
}

// How many times each item of `count` was marked by one dispatchCovering.
std::vector<unsigned> marksOfOneDispatch(const gl::Program& program, const glm::uvec3& count) {
    const std::size_t items = std::size_t{count.x} * count.y * count.z;
    gl::Buffer marks(items * sizeof(unsigned));
    marks.clearToZero();
    marks.bindStorage(0);
    program.use();
    glUniform3ui(program.uniform("count"), count.x, count.y, count.z);
    program.dispatchCovering(count.x, count.y, count.z);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    return marks.downloadAll<unsigned>();
}

TEST(GpuContract, ProgramReadsTheShadersWorkGroupSizeAtLinkTime) {
    test::glContext();
    for (const glm::uvec3 local : {glm::uvec3(8, 8, 1), glm::uvec3(64, 1, 1), glm::uvec3(5, 3, 2)})
        EXPECT_EQ(markProbe(local).workGroupSize(), local);
}

TEST(GpuContract, DispatchCoveringMarksEveryItemOnceWhateverTheLocalSize) {
    test::glContext();
    const glm::uvec3 count(37, 23, 5);  // divisible by none of the sizes below
    for (const glm::uvec3 local :
         {glm::uvec3(8, 8, 1), glm::uvec3(16, 4, 1), glm::uvec3(64, 1, 1), glm::uvec3(4, 4, 4), glm::uvec3(5, 3, 2)}) {
        const gl::Program program = markProbe(local);
        const glm::uvec3 groups = program.groupsCovering(count.x, count.y, count.z);
        EXPECT_EQ(groups, (count + local - 1u) / local) << local.x << "×" << local.y << "×" << local.z;
        const std::vector<unsigned> marks = marksOfOneDispatch(program, count);
        std::size_t wrong = 0;
        for (unsigned mark : marks) wrong += mark != 1u;
        EXPECT_EQ(wrong, 0u) << "items not marked exactly once at local size " << local.x << "×" << local.y << "×"
                             << local.z;
    }
}

TEST(GpuContract, DispatchGroupsDispatchesExactlyTheGroupsAsked) {
    test::glContext();
    const glm::uvec3 local(4, 2, 1);
    const gl::Program program = markProbe(local);
    const glm::uvec3 count(40, 40, 1);  // larger than the groups cover: only they mark
    const std::size_t items = std::size_t{count.x} * count.y;
    gl::Buffer marks(items * sizeof(unsigned));
    marks.clearToZero();
    marks.bindStorage(0);
    program.use();
    glUniform3ui(program.uniform("count"), count.x, count.y, count.z);
    program.dispatchGroups(3, 5);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    const std::vector<unsigned> result = marks.downloadAll<unsigned>();
    for (unsigned y = 0; y < count.y; ++y)
        for (unsigned x = 0; x < count.x; ++x) {
            const unsigned expected = x < 3 * local.x && y < 5 * local.y ? 1u : 0u;
            ASSERT_EQ(result[x + count.x * y], expected) << "item " << x << ", " << y;
        }
}

TEST(GpuContract, ARasterProgramHasNoWorkGroupsToCover) {
    test::glContext();
    const gl::Program raster;  // never linked as compute
    EXPECT_THROW(raster.groupsCovering(1), std::exception);
}

}  // namespace
}  // namespace eikon
